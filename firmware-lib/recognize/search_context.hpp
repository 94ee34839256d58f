// The state one pass of the stages shares (stages.hpp): the database, the
// pass's parameters, the workspace's buffers, the query's features and the
// answer being built. Each stage's functions are declared in its own header.
#pragma once
#include <cstdint>

#include "geometry/cell_grid.hpp"
#include "match/doublet.hpp"
#include "match/likelihood.hpp"
#include "spinhash/features.hpp"
#include "spinhash/internal/lsh_search.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"
#include "spinhash/vehicle_class.hpp"
#include "util/rng.hpp"

namespace spinhash {

// Best hypothesis of one model so far (gamma_i of section 9).
struct ModelBest {
  RigidPose pose;
  float score;
  uint32_t hypotheses;
  uint32_t inliers;
  bool has_score;
  bool final_score;  // rescored on every query feature
};

// One query feature's signed distance to the first model's surface, and the
// surface cell it lands on (residual_structure.cpp).
struct ResidualSample {
  uint32_t cell;
  uint32_t feature;
  float residual;
};

struct RecognizerBuffers {
  FeatureExtractor extractor;
  LshSearcher searcher;
  uint8_t* query_spins = nullptr;           // max_features * max_spin_dims
  Candidate* candidates = nullptr;          // max_features * candidate_stride
  uint32_t* candidate_count = nullptr;      // max_features
  float* cumulative = nullptr;              // max_features: sampling weights, running sum
  int32_t* matches = nullptr;               // max_features: the last verified pose's matches (refinement.cpp)
  ModelBest* best = nullptr;                // max_models
  RankedModel* ranking = nullptr;           // max_models
  uint32_t candidate_stride = 0;            // largest W of any mode
  CellGrid feature_grid;                    // the query features (visible_surface.cpp)
  ResidualSample* residuals = nullptr;      // max_features (residual_structure.cpp)
  RankedClass classes[kVehicleClassCount];  // Result::class_ranking
  // The cascade (recognizer.cpp): the first pass's settings, derived once at
  // init(), and the leading poses it hands to the full pass (carry.cpp).
  RecognizerConfig first_pass{};
  uint32_t carried_models[kMaxCarriedPoses] = {};
  RigidPose carried_poses[kMaxCarriedPoses];
  uint32_t carried_count = 0;
  // The first pass's answer, kept while the full pass runs: the answer a
  // capped full pass that names no posed model falls back to
  // (recognizer.cpp). Its ranking is the first kMaxCarriedPoses models; the
  // rest, and its class and group rankings, live in buffers the full pass
  // reuses.
  Result first_answer;
  RankedModel first_ranking[kMaxCarriedPoses];
  RankedGroup groups[kVehicleGroupCount];  // Result::group_ranking
};

// The leading model as BRAN's stop on evidence follows it (evidence_stop.cpp).
constexpr uint32_t kNoLeader = 0xFFFFFFFFu;
struct EvidenceState {
  uint32_t leader = kNoLeader;
  float leader_score = 0.0f;
  bool leader_moved = false;   // a new leader or a better pose since the bound was computed
  float miss_per_draw = 1.0f;  // 1 - q^2
  uint32_t draws = 0;          // stable doublets drawn
};

struct SearchContext {
  const Database& db;
  // This pass's settings: the stages' parameters (StageParams), the mode and
  // the seed; its capacities are those the workspace was carved for.
  const RecognizerConfig& params;
  Mode mode;
  uint32_t max_features;  // the workspace's (a sparse scan's lookups share its total)
  RecognizerBuffers& buf;
  Result& result;  // the answer being built; its stats are every stage's counts
  RecognitionStats& stats;
  OrientationHint hint;
  ObjectTerrain terrain;        // the caller's measure of the terrain, or none (top < 0)
  FeatureSet features;          // the ground and extract stages'
  QueryFeatures query;          // the features as the search sees them (spins quantised)
  LikelihoodParams likelihood;  // eqs. 4-7 with the draws' parameters
  DoubletTolerance tolerance;
  float d_min;
  float theta_min;
  float min_up_z;  // cos(max_tilt_deg): the least z of a posed model's up axis
  Pcg32 rng;
  const float* cumulative = nullptr;  // doublet draw weights (running sums); null = uniform
  EvidenceState evidence;
  uint32_t trial_scale = 1;  // BRAN's draws' budget x this (a sparse scan's; candidates.cpp)
  uint64_t work_before = 0;  // work units the cascade's earlier passes spent (work_meter.hpp)
  uint64_t work_cap = 0;     // the query's cap: params.max_work, or the caller's lower one
  // Whose calibrated thresholds decide this pass's flags (level_evidence.hpp).
  AnswerPass answer_pass = AnswerPass::kFull;

  SearchContext(const Database& database, const RecognizerConfig& pass, RecognizerBuffers& buffers,
                Result& answer);

  Candidate* candidates_of(uint32_t feature) const {
    return buf.candidates + static_cast<size_t>(feature) * buf.candidate_stride;
  }
  OrientedPoint query_point(uint32_t feature) const;
  OrientedPoint model_point(uint32_t feature) const;
};

// Model m holds a verified pose.
inline bool has_hypothesis(const SearchContext& ctx, uint32_t m) {
  return ctx.buf.best[m].has_score && ctx.buf.best[m].hypotheses > 0;
}

// Ranking order: higher score first, ties by model index.
inline bool scores_higher(const SearchContext& ctx, uint32_t a, uint32_t b) {
  const float sa = ctx.buf.best[a].score, sb = ctx.buf.best[b].score;
  return sa > sb || (sa == sb && a < b);
}

}  // namespace spinhash
