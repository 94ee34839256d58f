// State shared by the three recognition modes during one recognize() call.
#pragma once
#include <cstdint>

#include "geometry/cell_grid.hpp"
#include "match/doublet.hpp"
#include "match/likelihood.hpp"
#include "spinhash/features.hpp"
#include "spinhash/internal/lsh_search.hpp"
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
  RankedGroup groups[kVehicleGroupCount];   // Result::group_ranking
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
  const RecognizerConfig& cfg;
  RecognizerBuffers& buf;
  QueryFeatures query;
  LikelihoodParams likelihood;
  DoubletTolerance tolerance;
  float d_min;
  float theta_min;
  float min_up_z;  // cos(max_tilt_deg): the least z of a posed model's up axis
  RecognitionStats& stats;
  Pcg32 rng;
  const float* cumulative = nullptr;  // doublet draw weights (running sums); null = uniform
  EvidenceState evidence;
  uint32_t trial_scale = 1;  // BRAN's draws' budget x this (sparse_search.hpp)

  Candidate* candidates_of(uint32_t feature) const {
    return buf.candidates + static_cast<size_t>(feature) * buf.candidate_stride;
  }
  OrientedPoint query_point(uint32_t feature) const;
  OrientedPoint model_point(uint32_t feature) const;
};

// Draws two distinct query features by the cumulative weights (uniform when
// null) until they satisfy the stability constraints of eq. 3, at most
// kMaxStabilityRetries times. false when no stable pair was drawn.
bool draw_stable_doublet(SearchContext& ctx, uint32_t* k, uint32_t* l, DoubletShape* shape);

// Hypothesis budget: BRAN caps the total, SRAN each model's own RANSAC.
struct HypothesisCaps {
  uint32_t total;
  uint32_t per_model;
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

// Verifies `pose` of `model` and keeps it as gamma_model if it scores higher
// (the caller counts it in the stats). Dropped early when clearly worse than
// the model's best or, for a model without one, than `source_score` (the
// score of the look-alike a transferred pose comes from).
void consider_pose(SearchContext& ctx, uint32_t model, const RigidPose& pose,
                   float source_score = kNoScoreToBeat);

// What became of a candidate pair: stopped by the cascade or by its pose's
// tilt (max_tilt_deg), through both (and verified when the pose is
// defined), or not tried: the budget is spent.
enum class PairOutcome { kRejected, kPassed, kBudgetSpent };

// Cascade, pose, verification and gamma_i update for query features (k, l)
// matched to model features (fu, fv), verified as `model`'s.
PairOutcome evaluate_pair(SearchContext& ctx, uint32_t model, uint32_t k, uint32_t l,
                          const DoubletShape& shape, uint32_t fu, uint32_t fv, const HypothesisCaps& caps);

// Query feature l's candidates: `model`'s own top_w_sran nearest features
// (exhaustive scan; SRAN, the focused search), counted in the stats.
uint32_t gather_model_candidates(SearchContext& ctx, uint32_t model, uint32_t l);

// `trials` doublet draws among the current candidates, every candidate pair
// of a draw evaluated as `model`'s (all candidates are that model's: SRAN,
// the focused search). false once the budget is spent.
bool draw_for_model(SearchContext& ctx, uint32_t model, uint32_t trials, const HypothesisCaps& caps);

// Records `model`'s new best score for the stop on evidence (BRAN).
void note_leader(SearchContext& ctx, uint32_t model);
// true once more draws would most likely not change the leader (cfg.stop_miss_probability).
bool evidence_says_stop(SearchContext& ctx);

void run_bran(SearchContext& ctx);
// Lends the leading models' poses to the models whose boxes are nearest
// theirs (look-alikes crowded out of the W candidates; BRAN).
void transfer_poses(SearchContext& ctx);
// A short per-model RANSAC for each of the leading models, when the
// candidates are spread over look-alikes or the draws had to be extended
// past max_trials (focused_search.cpp; BRAN).
void focus_on_leaders(SearchContext& ctx);
// Rescores the leading models on all query features (refining their poses
// when asked) and puts every score on the all-features scale (BRAN, SRAN).
void finalise_scores(SearchContext& ctx, bool refine);
// Steps of the finalisation (refinement.cpp) that the final lending shares.
// The model's best pose scored on every feature of `all` (its matches kept
// in ctx.buf.matches); marks the score final.
void rescore_model(SearchContext& ctx, uint32_t model, const QueryFeatures& all, const LikelihoodParams& lp);
// Least-squares steps while they raise the score; `rescored`: ctx.buf.matches
// holds the matches of the model's best pose.
void refine_model(SearchContext& ctx, uint32_t model, const QueryFeatures& all, const LikelihoodParams& lp,
                  bool rescored);
// The model with the highest final score; false when none has one.
bool final_first(const SearchContext& ctx, uint32_t* first);
// After the leaders are finalised, the first model's pose lent to its
// look-alikes, which are rescored, refined and charged for their unseen
// surface alike (final_lending.cpp; BRAN with transfer_models > 0).
void lend_final_pose(SearchContext& ctx, const QueryFeatures& all, const LikelihoodParams& exact,
                     bool refine);
// What the scan shows of the model's upward surface under `pose`: each
// upward model feature seen (a query feature within Delta) or missed
// (visible_surface.cpp).
struct UpwardSurface {
  float log_likelihood = 0.0f;  // of the features seen and missed
  uint32_t facing = 0;          // model features facing up under the pose
  uint32_t seen = 0;            // of those, with a query feature within Delta
  // The share seen (RecognitionStats::surface_coverage); 0 when none faces up.
  float coverage() const { return facing ? static_cast<float>(seen) / static_cast<float>(facing) : 0.0f; }
};
UpwardSurface upward_surface(const SearchContext& ctx, uint32_t model, const RigidPose& pose);
// Indexes the query features for upward_surface (once per query).
void index_query_features(SearchContext& ctx);
// F of the residuals' means per surface cell against their scatter within
// the cells, for `model` under `pose`: about 1 when the scan is the model
// plus noise, large when a patch of it sits off the model's surface (a
// vehicle outside the database); 0 when too few features fall in shared
// cells to tell (residual_structure.cpp).
float residual_structure(const SearchContext& ctx, uint32_t model, const RigidPose& pose);
// Within a look-alike group (group_size >= 2: the first models lie within
// the margin, which the likelihood cannot separate), the model whose
// residuals are the scan's noise comes first: swaps ranking[0] and
// ranking[1] when the second's residual F is the lower. Its score may then
// be the lower of the two.
void order_twins_by_residuals(const SearchContext& ctx, RankedModel* ranking, uint32_t group_size);
void run_sran(SearchContext& ctx);
void run_sind(SearchContext& ctx);

}  // namespace spinhash
