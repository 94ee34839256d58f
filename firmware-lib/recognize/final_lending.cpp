// The final lending (not in the paper; BRAN; part of the refine stage,
// RefineParams::lend_*). After the leading models are
// refined, the first model's refined pose is lent to its nearest models by
// bounding box, each rescored on every feature, refined and charged for its
// unseen surface as the leaders were; when a look-alike then comes first,
// its own look-alikes get the same once more (lend_rounds).
//
// - Candidates spread over look-alikes (1000 near-identical models): the
//   scanned model was often a near neighbour of the wrong first one, whose
//   pose fits it within centimetres, but never refined. The pose is lent as
//   it is, to lend_spread_models models, and finalised on those where it
//   comes within lend_spread_window of the first on the hypothesis loop's
//   features (wider than the end-aligned window: only the refinement brings
//   a stretched copy's pose home).
// - Otherwise (a fleet of families): the scanned model was often a sibling
//   a metre shorter or longer than the first, or one the first fits the
//   wrong way round; the first's pose puts the sibling's centre where its
//   own was, off by half the difference in length, and the sibling's own
//   poses had not come near. A twin of the same length gets the pose as it
//   is: the in-loop transfer lent it the first's pose before the focused
//   search and refinement moved it (two identical tankers: the twin far
//   behind, so the first named confidently). The pose is lent to
//   lend_family_models models with the two boxes' rear ends, or front ends,
//   made to coincide, each also turned end to end; the best of these on the
//   hypothesis loop's features is finalised when it comes within
//   lend_end_aligned_window of the first there.
//
// Bounded: lend_rounds x (a screen of the first's own pose + look-alikes x
// (kEndAlignedPoses screens (one when spread) on the hypothesis loop's
// features + 1 + refine_iterations full verifications)), all counted
// (RefineStats); no round and no look-alike's screens begin once the query
// has spent its work cap (work_meter.hpp). Off with the transfer stage
// (TransferParams::enabled) or transfer_models 0, which also caps the
// look-alikes.
#include "recognize/final_lending.hpp"

#include "match/refine_pose.hpp"
#include "recognize/box_distance.hpp"
#include "recognize/refinement.hpp"
#include "recognize/visible_surface.hpp"
#include "recognize/work_meter.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

// Lent poses compared as the leaders were: rescored, refined, charged for
// the unseen upward surface. Keeps the better of this and a final score
// the model already had.
void finalise_lent(SearchContext& ctx, uint32_t model, const RigidPose& pose, const QueryFeatures& all,
                   const LikelihoodParams& exact, bool refine) {
  ModelBest& b = ctx.buf.best[model];
  const ModelBest before = b;
  b.pose = pose;
  b.has_score = true;
  ++b.hypotheses;
  rescore_model(ctx, model, all, exact);
  if (refine) refine_model(ctx, model, all, exact, true);
  b.score += upward_surface(ctx, model, b.pose).log_likelihood;
  if (before.final_score && !(b.score > before.score)) b = before;
}

// The best end-aligned pose of `target` from `source`'s on the hypothesis
// loop's features, when it reaches `floor`.
bool best_end_aligned(SearchContext& ctx, uint32_t source, uint32_t target, float floor, RigidPose* best) {
  float best_score = floor;
  bool found = false;
  for (uint32_t i = 0; i < kEndAlignedPoses; ++i) {
    RigidPose pose;
    if (!end_aligned_pose(ctx.buf.best[source].pose, ctx.db.model(source), ctx.db.model(target), i, &pose,
                          ctx.params.refine.lend_min_end_shift))
      continue;
    ++ctx.stats.refine.screens;
    const Verification v =
        verify_pose(ctx.db, target, pose, ctx.query, ctx.likelihood, best_score, kNoScoreToBeat);
    if (!v.complete || v.log_likelihood < best_score || (found && v.log_likelihood == best_score)) continue;
    best_score = v.log_likelihood;
    *best = pose;
    found = true;
  }
  return found;
}

// The floor a lent pose must reach on the hypothesis loop's features:
// `window` per feature below the source's own pose there.
float screen_floor(SearchContext& ctx, uint32_t source, float window) {
  ++ctx.stats.refine.screens;
  const float source_score = verify_pose(ctx.db, source, ctx.buf.best[source].pose, ctx.query, ctx.likelihood,
                                         kNoScoreToBeat, kNoScoreToBeat)
                                 .log_likelihood;
  return source_score - window * static_cast<float>(ctx.query.verify_count);
}

void lend_as_is(SearchContext& ctx, uint32_t source, const QueryFeatures& all, const LikelihoodParams& exact,
                bool refine, const uint32_t* targets, uint32_t n) {
  const RigidPose pose = ctx.buf.best[source].pose;  // no target is the source
  const float floor = screen_floor(ctx, source, ctx.params.refine.lend_spread_window);
  for (uint32_t t = 0; t < n && !work_capped(ctx); ++t) {
    ++ctx.stats.refine.screens;
    const Verification v =
        verify_pose(ctx.db, targets[t], pose, ctx.query, ctx.likelihood, floor, kNoScoreToBeat);
    if (v.complete && v.log_likelihood >= floor) finalise_lent(ctx, targets[t], pose, all, exact, refine);
  }
}

void lend_end_aligned(SearchContext& ctx, uint32_t source, const QueryFeatures& all,
                      const LikelihoodParams& exact, bool refine, const uint32_t* targets, uint32_t n) {
  const float floor = screen_floor(ctx, source, ctx.params.refine.lend_end_aligned_window);
  for (uint32_t t = 0; t < n && !work_capped(ctx); ++t) {
    RigidPose best;
    if (best_end_aligned(ctx, source, targets[t], floor, &best))
      finalise_lent(ctx, targets[t], best, all, exact, refine);
  }
}

}  // namespace

void lend_final_pose(SearchContext& ctx, const QueryFeatures& all, const LikelihoodParams& exact,
                     bool refine) {
  const bool spread = ctx.stats.candidates.spread;
  const RefineParams& p = ctx.params.refine;
  const TransferParams& t = ctx.params.transfer;
  const uint32_t cap = spread ? p.lend_spread_models : p.lend_family_models;  // <= kMaxLendModels
  const uint32_t wanted = !t.enabled ? 0u : (t.transfer_models < cap ? t.transfer_models : cap);
  if (wanted == 0u) return;                   // the transfer off: the paper's BRAN
  uint32_t lent_from = ctx.db.model_count();  // none yet
  for (uint32_t round = 0; round < p.lend_rounds && !work_capped(ctx); ++round) {
    uint32_t first = 0;
    if (!final_first(ctx, &first) || first == lent_from) return;
    uint32_t targets[kMaxLendModels];
    // Spread: only models not yet finalised (the leaders were refined from their own poses).
    const uint32_t n = nearest_by_box(ctx.db, first, wanted, targets, [&](uint32_t m) {
      return m != first && (!spread || !ctx.buf.best[m].final_score);
    });
    if (spread)
      lend_as_is(ctx, first, all, exact, refine, targets, n);
    else
      lend_end_aligned(ctx, first, all, exact, refine, targets, n);
    lent_from = first;
  }
}

}  // namespace spinhash
