// The other half of the fit (not in the paper): eq. 7 scores how well a
// model explains the query, never whether the query shows what the model
// would have shown. A longer bus explains every point of a shorter one's
// scan, so larger look-alikes win. From the air the roof, the hood and the
// deck face the sensor whatever the side scanned: every model feature facing
// up under the pose should have query features within Delta: each one is
// seen or missed with the probabilities below. The share seen is also the
// first model's surface_coverage, which the confidence margin reads
// (confidence.hpp). Bounded: for each of the kRefinedModels leaders, the
// lent look-alikes and the first model once more, the model's features x
// the query features in at most 8 cells of a grid twice Delta wide (found
// in the query features' grid, built once per query).
#include "recognize/search_context.hpp"

namespace spinhash {
namespace {

// A model feature faces the sensor when its posed normal is within 45
// degrees of the vertical (z up in the query frame; the sensor is above).
constexpr float kUpwardNormalZ = 0.7071f;
// A patch of the right model facing the sensor returns no point with this
// probability (occluded by a tree or another vehicle, cut by segmentation,
// a dark or wet surface): log p of a patch seen and of one missed.
constexpr float kLogSeen = -0.35667f;    // log(1 - 0.3)
constexpr float kLogMissed = -1.20397f;  // log(0.3)

// The query features in cells twice Delta wide: a posed model feature's
// neighbours within Delta lie in at most 8 of them.
constexpr float kGridCellsPerDelta = 2.0f;

}  // namespace

void index_query_features(SearchContext& ctx) {
  ctx.buf.feature_grid.build(ctx.query.positions, ctx.query.count, kGridCellsPerDelta * ctx.cfg.delta);
}

UpwardSurface upward_surface(const SearchContext& ctx, uint32_t model, const RigidPose& pose) {
  const blob::ModelRecord& rec = ctx.db.model(model);
  UpwardSurface u;
  for (uint32_t f = rec.first_feature; f < rec.first_feature + rec.feature_count; ++f) {
    const OrientedPoint m = ctx.model_point(f);
    if ((pose.rotation * m.n)[2] < kUpwardNormalZ) continue;
    const Eigen::Vector3f x = pose.rotation * m.p + pose.translation;
    const bool seen = ctx.buf.feature_grid.any_within(x.data(), ctx.cfg.delta);
    u.log_likelihood += seen ? kLogSeen : kLogMissed;
    ++u.facing;
    u.seen += seen ? 1u : 0u;
  }
  return u;
}

}  // namespace spinhash
