// The recognizer: a validated Database plus a caller-owned workspace in, a
// ranked list of models with poses out. No heap; every buffer is carved from
// the workspace at init(); recognize() is bounded by the config's work budget.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>

#include "spinhash/calibration.hpp"
#include "spinhash/config.hpp"
#include "spinhash/database.hpp"
#include "spinhash/features.hpp"
#include "spinhash/status.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash {

// x_query = rotation * x_model + translation; rotation row-major.
// translation is in the input's coordinates (georeferenced clouds included).
struct Pose {
  float rotation[9];
  double translation[3];
};

struct RankedModel {
  uint32_t model = 0;  // index into the database's model table
  float score = 0.0f;  // larger is better: log-likelihood (BRAN, SRAN), votes (SIND)
  Pose pose{};         // best pose found for this model (identity for SIND)
  bool has_pose = false;
  uint32_t hypotheses = 0;  // poses verified for this model
  uint32_t inliers = 0;     // query features within Delta under the best pose
};

// One vehicle class of the database (vehicle_classes.h), scored by its best
// model: the level an answer can give when the scan does not tell one model
// from another (a sparse scan: "a pickup", not which).
struct RankedClass {
  uint32_t vehicle_class = 0;  // VehicleClass id (vehicle_class_name())
  float score = 0.0f;          // its best model's score (RankedModel::score)
  uint32_t model = 0;          // that model (database index)
  uint32_t best_rank = 0;      // that model's place in Result::ranking
};

// One vehicle group of the database (its models' groups: vehicle_group_of()),
// scored by its best model: what a scan too sparse or too unlike every model
// for a class still tells (a light vehicle, not a bus).
struct RankedGroup {
  uint32_t group = 0;      // VehicleGroup id
  float score = 0.0f;      // its best model's score (RankedModel::score)
  uint32_t model = 0;      // that model (database index)
  uint32_t best_rank = 0;  // that model's place in Result::ranking
};

// A calibrated level's evidence and flag (answer_levels.h): the flag is the
// evidence at or above the database's threshold for the scan's density
// (Database::calibration()), or the recognizer's priors without a fitted
// table. Evidence is -infinity when a prerequisite of the level fails.
struct LevelAnswer {
  float evidence = -std::numeric_limits<float>::infinity();
  bool confident = false;
};

// What each stage did (the stages of stage_fields.h that count something).
struct GroundStats {
  uint32_t points_ground = 0;  // dropped as terrain (geometry/object_ground.hpp)
};
struct CandidatesStats {
  uint64_t kept = 0;                   // candidate model features kept (sum of W_l; SRAN and focus too)
  uint64_t bucket_entries = 0;         // LSH entries scanned
  uint32_t salient_features = 0;       // features with candidates that sampling may draw
  bool spread = false;                 // BRAN: the candidates named many look-alikes (spread_perplexity)
  bool bucket_scan_truncated = false;  // some LSH lookups hit max_bucket_scan
};
// The hypothesis machinery's counts: the draws', and the focused search's,
// which draws through the same cascade.
struct DrawsStats {
  uint32_t trials = 0;               // doublet draws
  uint64_t pair_checks = 0;          // candidate pairs put through the cascade
  uint64_t doublets_passed = 0;      // pairs that passed the cascade
  uint64_t poses_tilted = 0;         // their poses tilted past max_tilt_deg, not verified
  uint32_t hypotheses = 0;           // poses verified from doublets (max_hypotheses: poses_found())
  bool budget_exhausted = false;     // the work budget cut recognition short
  bool stopped_on_evidence = false;  // BRAN stopped before the budget (stop_miss_probability)
  // The poses the doublets gave, verified or refused for their tilt: what
  // BRAN's pose budget and its draw extension count (max_hypotheses,
  // min_hypotheses).
  uint64_t poses_found() const { return hypotheses + poses_tilted; }
};
struct TransferStats {
  uint32_t transferred = 0;  // look-alike pose transfers verified
};
// The refine stage's (its final lending's included).
struct RefineStats {
  uint32_t refinements = 0;  // least-squares pose refinements verified
  uint32_t rescores = 0;     // poses scored on every query feature: leaders', turned, lent
  // Poses scored on the hypothesis loop's features to choose what to refine
  // and lend: the turn screen, the lending's floor and its lent poses.
  uint32_t screens = 0;
};
struct ConfidenceStats {
  // The share of the first model's upward-facing surface (under its pose)
  // with a query feature within Delta: how much of the vehicle the scan
  // shows from the air, which occlusion and sparsity lower; 0 without a pose.
  float surface_coverage = 0.0f;
  // Object points (after terrain removal) per m^2 of the first model's box
  // top the scan spans, under its pose: how densely the scan samples the
  // vehicle, whatever the occlusion; 0 without a pose.
  float scan_density = 0.0f;
};

struct CarryStats {
  uint32_t carried = 0;  // first-pass poses verified on the full pass's features
};
// The cascade (RecognizerConfig::cascade): the stage blocks above count the
// pass that answered; this one, every pass's work (work units,
// firmware-lib/recognize/work_meter.hpp).
struct CascadeStats {
  uint32_t passes = 0;       // passes run: 1, or 2 when the first pass did not stop the query
  uint32_t answered_by = 0;  // the pass that answered: 0 the first (flight), 1 the full
  uint64_t first_work = 0;   // work of the first pass (0 when the cascade is off)
  uint64_t full_work = 0;    // work of the full pass (0 when the first pass answered)
  uint64_t work = 0;         // the query's total, which RecognizerConfig::max_work caps
  bool work_capped = false;  // max_work was reached (Status::kWorkCapReached)
  // The first pass answered, not confident, because the database's agree
  // table says stopping there loses no right answer the full pass would give.
  bool stopped_on_agreement = false;
};

struct RecognitionStats {
  ExtractStats extract;
  GroundStats ground;
  CandidatesStats candidates;
  CarryStats carry;
  DrawsStats draws;
  TransferStats transfer;
  RefineStats refine;
  ConfidenceStats confidence;
  CascadeStats cascade;
  size_t workspace_used = 0;
};

struct Result {
  Status status = Status::kNotOpen;
  const RankedModel* ranking = nullptr;  // in the workspace; valid until the next call
  uint32_t ranking_count = 0;            // models that got a score, best first
  // The first model is named confidently: the model level's flag
  // (levels[level_index(AnswerLevel::kModel)].confident).
  bool confident = false;
  // Look-alike group: the first group_size models of the ranking score within
  // min_margin x sqrt(features) log-likelihood of the first (spread_margin_factor
  // times that when stats.candidates.spread: among many look-alikes), so the
  // scan does not tell them apart (BRAN, SRAN). 1: the first stands alone
  // (always for SIND, which ranks by votes); 0: no ranking.
  uint32_t group_size = 0;
  // The classes of the ranked models, best first (by their best model's
  // score; ties by class id); in the workspace like `ranking`.
  const RankedClass* class_ranking = nullptr;
  uint32_t class_ranking_count = 0;
  // The first class is named confidently: the class level's flag
  // (levels[level_index(AnswerLevel::kClass)].confident; docs/api.md).
  bool class_confident = false;
  // The groups of the ranked models, best first (ties by group id), like
  // class_ranking.
  const RankedGroup* group_ranking = nullptr;
  uint32_t group_ranking_count = 0;
  // Per calibrated level, vehicle .. model (index level_index()).
  LevelAnswer levels[kCalibratedLevels];
  // The most specific confident level whose coarser levels are all
  // confident and consistent (the model is of the first class, which is of
  // the first group); kNone when not even the vehicle level is.
  AnswerLevel level = AnswerLevel::kNone;
  RecognitionStats stats;
};

struct RecognizerBuffers;  // the workspace layout (firmware-lib/recognize)

// Workspace bytes init() needs for `config` (aligned to kBufferAlignment).
size_t required_workspace_bytes(const RecognizerConfig& config) noexcept;

// The terrain under an object that the caller measured (a scene's terrain
// classifier): the object's top above it and the terrain's noise, m. The
// class flag tests the top against the class's envelope (docs/api.md,
// class_confident) as it does the top above terrain that the object ground
// removal finds in a cut-out with its ground.
struct ObjectTerrain {
  float top = -1.0f;  // m above the terrain; < 0: not measured
  float sigma = 0.0f;
  float band = 0.0f;  // m above the terrain below which the caller removed the points (as ground)
};

class Recognizer {
 public:
  Status init(const Database* db, const RecognizerConfig& config, void* workspace,
              size_t workspace_bytes) noexcept;
  Result recognize(const float* xyz, uint32_t count) noexcept;
  Result recognize(const double* xyz, uint32_t count) noexcept;
  Result recognize(const float* xyz, uint32_t count, const ObjectTerrain& terrain) noexcept;
  size_t used_bytes() const noexcept { return used_bytes_; }
  const RecognizerConfig& config() const noexcept { return config_; }
  // Caps the work of the queries that follow at `units` when that is below
  // config().max_work (kNoWorkCap lifts it): for a caller that shares one
  // budget among queries, as a scene window does among its objects. A
  // query that reaches it ends as at max_work (Status::kWorkCapReached).
  static constexpr uint64_t kNoWorkCap = ~0ull;
  void set_work_cap(uint64_t units) noexcept { work_cap_ = units; }

 private:
  Result run(const CloudView& cloud, const ObjectTerrain& terrain) noexcept;

  const Database* db_ = nullptr;
  RecognizerConfig config_{};
  size_t used_bytes_ = 0;
  RecognizerBuffers* buffers_ = nullptr;  // placed in the workspace by init()
  uint64_t work_cap_ = kNoWorkCap;        // set_work_cap()
};

}  // namespace spinhash
