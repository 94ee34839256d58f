// Sequential RANSAC, the paper's SRAN baseline: every model in turn, with its
// own W nearest features per query feature (exhaustive per model, as a
// per-model matcher does) and its own trials, through the same cascade, pose
// and likelihood as BRAN. Cost grows linearly with the number of models.
#include "recognize/search_context.hpp"

namespace spinhash {

void run_sran(SearchContext& ctx) {
  const HypothesisCaps caps{0xFFFFFFFFu, ctx.cfg.max_hypotheses};
  for (uint32_t model = 0; model < ctx.db.model_count(); ++model) {
    for (uint32_t l = 0; l < ctx.query.count; ++l) gather_model_candidates(ctx, model, l);
    draw_for_model(ctx, model, ctx.cfg.sran_trials, caps);         // a model's own cap ends its draws only
    if (ctx.stats.pair_checks >= ctx.cfg.max_pair_checks) return;  // global budget spent
  }
}

}  // namespace spinhash
