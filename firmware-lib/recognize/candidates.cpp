#include "recognize/candidates.hpp"

#include <cmath>

#include "recognize/sparse_search.hpp"
#include "recognize/work_meter.hpp"

namespace spinhash {
namespace {

// The candidates are spread over look-alikes when their perplexity (the
// number of models they name, exp(H)) averages more than spread_perplexity
// (harmonic mean over the features with candidates): two features then
// rarely hold candidates of one model. Never reached with W below it.
bool candidates_spread(const SearchContext& ctx) {
  const float inverse_perplexity_sum = ctx.buf.cumulative[ctx.query.count - 1u];  // sum of exp(-H)
  return inverse_perplexity_sum * ctx.params.candidates.spread_perplexity <
         static_cast<float>(ctx.stats.candidates.salient_features);
}

// The bucket entries scanned so far counted; true when they reach the
// query's cap (the features after this one then get no candidates).
bool scan_capped(SearchContext& ctx, const SearchStats& ss) {
  ctx.stats.candidates.bucket_entries = ss.entries_scanned;
  ctx.stats.candidates.bucket_scan_truncated = ss.truncated;
  return work_capped(ctx);
}

// Candidates and saliency weights of every query feature (BRAN), up to the cap.
void gather_candidates(SearchContext& ctx, uint32_t w) {
  RecognizerBuffers& b = ctx.buf;
  CandidatesStats& st = ctx.stats.candidates;
  SearchStats ss;
  float running = 0.0f;
  bool capped = false;
  for (uint32_t l = 0; l < ctx.query.count; ++l) {
    uint32_t n = 0;
    if (!capped) {
      Candidate* list = ctx.candidates_of(l);
      n = b.searcher.search(ctx.db, ctx.query.spins + static_cast<size_t>(l) * ctx.query.dims, w, list, &ss);
      // exp(-H) = 1 / perplexity: a feature whose candidates name one model is
      // drawn as often as one spread evenly over e.g. 20 models, 20 times.
      if (n > 0) {
        running += std::exp(-candidate_entropy(ctx.db, list, n));
        ++st.salient_features;
      }
      capped = scan_capped(ctx, ss);
    }
    b.candidate_count[l] = n;
    st.kept += n;
    b.cumulative[l] = running;
  }
}

// Spin-image indexing without geometry, the paper's SIND baseline: each
// query feature votes for the models of its W nearest database features.
void vote(SearchContext& ctx) {
  CandidatesStats& st = ctx.stats.candidates;
  SearchStats ss;
  for (uint32_t l = 0; l < ctx.query.count; ++l) {
    Candidate* list = ctx.candidates_of(l);
    uint32_t n = ctx.buf.searcher.search(ctx.db, ctx.query.spins + static_cast<size_t>(l) * ctx.query.dims,
                                         ctx.params.candidates.top_w_sind, list, &ss);
    st.kept += n;
    for (uint32_t i = 0; i < n; ++i) {
      ModelBest& best = ctx.buf.best[ctx.db.feature_models()[list[i].feature]];
      best.score = best.has_score ? best.score + 1.0f : 1.0f;
      best.has_score = true;
    }
    if (scan_capped(ctx, ss)) break;  // the votes so far answer
  }
}

}  // namespace

Status candidates_stage(SearchContext& ctx) {
  const ExtractStats& e = ctx.stats.extract;
  const uint32_t dropped = e.points_nonfinite + ctx.stats.ground.points_ground;
  const float density = footprint_density(ctx.query, e.points_in > dropped ? e.points_in - dropped : 0u);
  ctx.trial_scale = trial_scale(ctx.params, density);
  ctx.buf.searcher.set_scan(bucket_scan(ctx.params, ctx.max_features, density, ctx.query.count));
  if (ctx.mode == Mode::kSind) {
    vote(ctx);
  } else if (ctx.mode == Mode::kBran) {
    gather_candidates(ctx, ctx.params.candidates.top_w);
    if (ctx.stats.candidates.salient_features >= 2u) ctx.stats.candidates.spread = candidates_spread(ctx);
  }
  return Status::kOk;
}

}  // namespace spinhash
