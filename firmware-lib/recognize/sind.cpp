// Spin-image indexing without geometry, the paper's SIND baseline: each query
// feature votes for the models of its W nearest database features.
#include "recognize/search_context.hpp"

namespace spinhash {

void run_sind(SearchContext& ctx) {
  SearchStats ss;
  for (uint32_t l = 0; l < ctx.query.count; ++l) {
    Candidate* list = ctx.candidates_of(l);
    uint32_t n = ctx.buf.searcher.search(ctx.db, ctx.query.spins + static_cast<size_t>(l) * ctx.query.dims,
                                         ctx.cfg.top_w_sind, list, &ss);
    ctx.stats.candidates += n;
    for (uint32_t i = 0; i < n; ++i) {
      ModelBest& best = ctx.buf.best[ctx.db.feature_models()[list[i].feature]];
      best.score = best.has_score ? best.score + 1.0f : 1.0f;
      best.has_score = true;
    }
  }
  ctx.stats.bucket_entries = ss.entries_scanned;
  ctx.stats.bucket_scan_truncated = ss.truncated;
}

}  // namespace spinhash
