#include "recognize/visible_surface.hpp"

namespace spinhash {
namespace {

// The query features in cells twice Delta wide: a posed model feature's
// neighbours within Delta lie in at most 8 of them.
constexpr float kGridCellsPerDelta = 2.0f;

}  // namespace

void index_query_features(SearchContext& ctx) {
  ctx.buf.feature_grid.build(ctx.query.positions, ctx.query.count,
                             kGridCellsPerDelta * ctx.params.draws.delta);
}

UpwardSurface upward_surface(const SearchContext& ctx, uint32_t model, const RigidPose& pose) {
  const blob::ModelRecord& rec = ctx.db.model(model);
  const RefineParams& p = ctx.params.refine;
  UpwardSurface u;
  for (uint32_t f = rec.first_feature; f < rec.first_feature + rec.feature_count; ++f) {
    const OrientedPoint m = ctx.model_point(f);
    if ((pose.rotation * m.n)[2] < p.upward_normal_z) continue;
    const Eigen::Vector3f x = pose.rotation * m.p + pose.translation;
    const bool seen = ctx.buf.feature_grid.any_within(x.data(), ctx.params.draws.delta);
    u.log_likelihood += seen ? p.log_seen : p.log_missed;
    ++u.facing;
    u.seen += seen ? 1u : 0u;
  }
  return u;
}

}  // namespace spinhash
