#include "recognize/ranking.hpp"

#include "recognize/confidence.hpp"
#include "recognize/residual_structure.hpp"
#include "util/heap_sort.hpp"

namespace spinhash {
namespace {

Pose to_public_pose(const RigidPose& p, const double origin[3]) {
  Pose out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.rotation[3 * r + c] = p.rotation(r, c);
  for (int a = 0; a < 3; ++a) out.translation[a] = static_cast<double>(p.translation[a]) + origin[a];
  return out;
}

Pose identity_pose() {
  Pose p{};
  p.rotation[0] = p.rotation[4] = p.rotation[8] = 1.0f;
  return p;
}

uint32_t rank_models(const Database& db, RecognizerBuffers& b, const double origin[3]) {
  uint32_t n = 0;
  for (uint32_t m = 0; m < db.model_count(); ++m) {
    const ModelBest& best = b.best[m];
    if (!best.has_score) continue;
    RankedModel& r = b.ranking[n++];
    r.model = m;
    r.score = best.score;
    r.has_pose = best.hypotheses > 0;
    r.pose = r.has_pose ? to_public_pose(best.pose, origin) : identity_pose();
    r.hypotheses = best.hypotheses;
    r.inliers = best.inliers;
  }
  // Best first; equal scores by model index, so the order is fully determined.
  heap_sort(b.ranking, n, [](const RankedModel& x, const RankedModel& y) {
    return x.score > y.score || (x.score == y.score && x.model < y.model);
  });
  return n;
}

}  // namespace

Status rank_stage(SearchContext& ctx) {
  Result& result = ctx.result;
  result.ranking = ctx.buf.ranking;
  result.ranking_count = rank_models(ctx.db, ctx.buf, ctx.features.origin);
  result.group_size = lookalike_group_size(result, ctx.params, ctx.features.count);
  if (ctx.params.rank.twins_by_residuals) order_twins_by_residuals(ctx, ctx.buf.ranking, result.group_size);
  return Status::kOk;
}

}  // namespace spinhash
