// BRAN's focused search (not in the paper). When the joint candidates are
// spread over many look-alikes (bran.cpp: each query feature's W candidates
// name a few dozen near-identical models), or so few poses were verified
// that the draws were extended past max_trials (min_hypotheses), few
// doublets pair up in one model, and the true model may hold only a handful
// of poorer poses (or a look-alike's, lent by the pose transfer). The
// leading models after the draws are then nearly all of the right family,
// so each of the cfg.focus_models best gets the short RANSAC that SRAN
// gives every model: its own top_w_sran nearest features for an evenly
// spread share of the query features, and kFocusTrials draws through the
// same cascade and likelihood. Bounded: focus_models x (the searched
// features x one model's features) descriptor distances, and kFocusTrials x
// top_w_sran^2 pair checks per model, within max_pair_checks.
#include "recognize/search_context.hpp"
#include "spinhash/limits.hpp"
#include "util/top_n.hpp"

namespace spinhash {
namespace {

// The model's own candidates for every step-th query feature (none for the
// others), and uniform draw weights over the features that got some.
void gather_subset_candidates(SearchContext& ctx, uint32_t model, uint32_t step) {
  float searched = 0.0f;
  for (uint32_t l = 0; l < ctx.query.count; ++l) {
    ctx.buf.candidate_count[l] = 0u;
    if (l % step == 0u && gather_model_candidates(ctx, model, l) > 0u) searched += 1.0f;
    ctx.buf.cumulative[l] = searched;
  }
}

}  // namespace

void focus_on_leaders(SearchContext& ctx) {
  uint32_t models[kMaxFocusModels];
  const uint32_t n = top_n(
      ctx.db.model_count(), ctx.cfg.focus_models, models, [&](uint32_t m) { return has_hypothesis(ctx, m); },
      [&](uint32_t a, uint32_t b) { return scores_higher(ctx, a, b); });
  // Every step-th feature: about verify_count of them, the hypotheses' subset size.
  const uint32_t step = (ctx.query.count + ctx.query.verify_count - 1u) / ctx.query.verify_count;
  ctx.cumulative = ctx.buf.cumulative;
  const HypothesisCaps caps{0xFFFFFFFFu, ctx.cfg.max_hypotheses};
  for (uint32_t i = 0; i < n; ++i) {
    gather_subset_candidates(ctx, models[i], step);
    if (!draw_for_model(ctx, models[i], kFocusTrials, caps)) return;
  }
}

}  // namespace spinhash
