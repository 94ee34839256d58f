#include "recognize/pose_transfer.hpp"

#include "recognize/box_distance.hpp"
#include "recognize/hypotheses.hpp"
#include "recognize/work_meter.hpp"
#include "spinhash/limits.hpp"
#include "util/top_n.hpp"

namespace spinhash {

Status transfer_stage(SearchContext& ctx) {
  const TransferParams& p = ctx.params.transfer;
  const uint32_t wanted = p.transfer_models;  // <= kMaxTransferModels (config_valid)
  if (ctx.mode != Mode::kBran || wanted == 0u) return Status::kOk;
  const uint32_t model_count = ctx.db.model_count();
  uint32_t sources[kMaxTransferPoses];
  const uint32_t n_sources = top_n(
      model_count, p.transfer_poses, sources, [&](uint32_t m) { return has_hypothesis(ctx, m); },
      [&](uint32_t a, uint32_t b) { return scores_higher(ctx, a, b); });
  RigidPose poses[kMaxTransferPoses];  // copied: consider_pose may replace a source's own pose
  float scores[kMaxTransferPoses];
  for (uint32_t i = 0; i < n_sources; ++i) {
    poses[i] = ctx.buf.best[sources[i]].pose;
    scores[i] = ctx.buf.best[sources[i]].score;
  }
  uint32_t targets[kMaxTransferModels];
  for (uint32_t i = 0; i < n_sources; ++i) {
    const uint32_t n =
        nearest_by_box(ctx.db, sources[i], wanted, targets, [&](uint32_t m) { return m != sources[i]; });
    for (uint32_t t = 0; t < n && !work_capped(ctx); ++t) {
      ++ctx.stats.transfer.transferred;
      consider_pose(ctx, targets[t], poses[i], scores[i]);
    }
  }
  return Status::kOk;
}

}  // namespace spinhash
