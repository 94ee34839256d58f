// Sequential RANSAC, the paper's SRAN baseline: every model in turn, with its
// own W nearest features per query feature (exhaustive per model, as a
// per-model matcher does) and its own trials, through the same cascade, pose
// and likelihood as BRAN. Cost grows linearly with the number of models.
#include "recognize/search_context.hpp"

namespace spinhash {

void run_sran(SearchContext& ctx) {
  const uint32_t w = ctx.cfg.top_w_sran;
  const HypothesisCaps caps{0xFFFFFFFFu, ctx.cfg.max_hypotheses};
  RecognizerBuffers& b = ctx.buf;
  for (uint32_t model = 0; model < ctx.db.model_count(); ++model) {
    for (uint32_t l = 0; l < ctx.query.count; ++l) {
      b.candidate_count[l] = search_model_exhaustive(
          ctx.db, model, ctx.query.spins + static_cast<size_t>(l) * ctx.query.dims, w, ctx.candidates_of(l));
      ctx.stats.candidates += b.candidate_count[l];
    }
    draw_for_model(ctx, model, ctx.cfg.sran_trials, caps);         // a model's own cap ends its draws only
    if (ctx.stats.pair_checks >= ctx.cfg.max_pair_checks) return;  // global budget spent
  }
}

}  // namespace spinhash
