// The hypothesis machinery shared by the draws (BRAN, SRAN), the focused
// search and the pose transfer: doublet draws, the Figure 5 cascade, the
// pose and its likelihood.
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

// Draws two distinct query features by the cumulative weights (uniform when
// null) until they satisfy the stability constraints of eq. 3, at most
// kMaxStabilityRetries times. false when no stable pair was drawn.
bool draw_stable_doublet(SearchContext& ctx, uint32_t* k, uint32_t* l, DoubletShape* shape);

// Hypothesis budget: BRAN caps the total, SRAN each model's own RANSAC.
struct HypothesisCaps {
  uint32_t total;
  uint32_t per_model;
};

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

}  // namespace spinhash
