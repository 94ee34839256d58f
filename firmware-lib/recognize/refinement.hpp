// The refine stage (BRAN, SRAN; stage_fields.h: RefineParams). After the
// hypothesis loop, which scores poses on a subset of the query features
// (through the blob's nearest-feature field when it has one), the
// rescored_models leading models' best poses are rescored on every feature
// with the exact nearest-feature search and the surface residual
// (make_surface_params: each query feature's distance to the model's surface
// along the nearest model feature's normal, with sigma_surface; the paper's
// distance to the feature itself carries the basis voxels' sampling offset,
// which blurs the centimetres that separate look-alikes); those within
// refine_window of the best are (refine_poses) refined point to plane
// (match/refine_pose.hpp), from the pose as found and, when it is close on
// the hypothesis loop's features (turn_screen_slack), from the pose turned
// end to end (a near-symmetric vehicle's hypothesis may come the wrong way
// round), keeping the refined pose with the higher likelihood; BRAN then
// charges each for the upward surface the scan does not show
// (visible_surface.hpp) and lends the first model's refined pose to its
// look-alikes (final_lending.hpp); every other model's subset score is
// extrapolated to all features, below the rescored ones. Bounded:
// rescored_models x (2 + 2 refine_iterations) full verifications and 2
// screens on the hypothesis loop's features, and the lending's own bound,
// all counted (RefineStats). The work cap (work_meter.hpp) is checked before
// each leader's rescoring and each refinement (the turned pose's its own):
// once spent, the leaders rescored so far are finalised as they stand and
// the others keep their subset scores, below them.
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

Status refine_stage(SearchContext& ctx);

// Steps the final lending shares.
// The model's best pose scored on every feature of `all` (its matches kept
// in ctx.buf.matches); marks the score final.
void rescore_model(SearchContext& ctx, uint32_t model, const QueryFeatures& all, const LikelihoodParams& lp);
// Least-squares steps while they raise the score; `rescored`: ctx.buf.matches
// holds the matches of the model's best pose.
void refine_model(SearchContext& ctx, uint32_t model, const QueryFeatures& all, const LikelihoodParams& lp,
                  bool rescored);
// The model with the highest final score; false when none has one.
bool final_first(const SearchContext& ctx, uint32_t* first);

}  // namespace spinhash
