#include "recognize/focused_search.hpp"

#include "recognize/draws.hpp"
#include "recognize/hypotheses.hpp"
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

// Candidates spread over look-alikes, or so few poses that the draws were
// extended, and budget left.
bool worth_focusing(const SearchContext& ctx) {
  const DrawsStats& d = ctx.stats.draws;
  return (ctx.stats.candidates.spread || d.trials > trial_budget(ctx)) && !d.budget_exhausted;
}

}  // namespace

Status focus_stage(SearchContext& ctx) {
  if (ctx.mode != Mode::kBran || !worth_focusing(ctx)) return Status::kOk;
  uint32_t models[kMaxFocusModels];
  const uint32_t n = top_n(
      ctx.db.model_count(), ctx.params.focus.focus_models, models,
      [&](uint32_t m) { return has_hypothesis(ctx, m); },
      [&](uint32_t a, uint32_t b) { return scores_higher(ctx, a, b); });
  // Every step-th feature: about verify_count of them, the hypotheses' subset size.
  const uint32_t step = (ctx.query.count + ctx.query.verify_count - 1u) / ctx.query.verify_count;
  ctx.cumulative = ctx.buf.cumulative;
  const HypothesisCaps caps{0xFFFFFFFFu, ctx.params.draws.max_hypotheses};
  for (uint32_t i = 0; i < n; ++i) {
    gather_subset_candidates(ctx, models[i], step);
    if (!draw_for_model(ctx, models[i], ctx.params.focus.focus_trials, caps)) break;
  }
  return Status::kOk;
}

}  // namespace spinhash
