#include "recognize/carry.hpp"

#include "recognize/hypotheses.hpp"

namespace spinhash {

Status carry_stage(SearchContext& ctx) {
  if (ctx.mode == Mode::kSind || ctx.query.count == 0) return Status::kOk;  // no poses; no features (capped)
  RecognizerBuffers& b = ctx.buf;
  const uint32_t limit = ctx.params.carry.carry_models;
  const uint32_t n = b.carried_count < limit ? b.carried_count : limit;
  for (uint32_t i = 0; i < n; ++i) {
    if (b.carried_models[i] >= ctx.db.model_count()) continue;
    consider_pose(ctx, b.carried_models[i], b.carried_poses[i]);
    ++ctx.stats.carry.carried;
  }
  return Status::kOk;
}

void keep_leading_poses(SearchContext& ctx) {
  RecognizerBuffers& b = ctx.buf;
  b.carried_count = 0;
  for (uint32_t r = 0; r < ctx.result.ranking_count && b.carried_count < kMaxCarriedPoses; ++r) {
    const uint32_t m = ctx.result.ranking[r].model;
    if (!has_hypothesis(ctx, m)) continue;
    b.carried_models[b.carried_count] = m;
    b.carried_poses[b.carried_count] = b.best[m].pose;
    ++b.carried_count;
  }
}

}  // namespace spinhash
