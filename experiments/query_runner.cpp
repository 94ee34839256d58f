#include "query_runner.hpp"

namespace spinhash::experiment {

Outcome recognise(pipeline::RecognitionSession& session, const Query& q) {
  Result r = session.recognize(q.xyz);
  Outcome o;
  o.status = r.status;
  o.ms = session.last_ms();
  o.hypotheses = r.stats.hypotheses;
  o.features = r.stats.features;
  o.confident = r.confident;
  o.budget_exhausted = r.stats.budget_exhausted;
  if (r.status != Status::kOk) return o;
  o.ranked = r.ranking_count;
  if (r.ranking_count > 0) o.best_model = r.ranking[0].model;
  for (uint32_t i = 0; i < r.ranking_count; ++i)
    if (r.ranking[i].model == q.model) {
      o.rank = i + 1u;
      break;
    }
  return o;
}

}  // namespace spinhash::experiment
