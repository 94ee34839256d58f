// The other half of the fit (not in the paper): eq. 7 scores how well a
// model explains the query, never whether the query shows what the model
// would have shown. A longer bus explains every point of a shorter one's
// scan, so larger look-alikes win. From the air the roof, the hood and the
// deck face the sensor whatever the side scanned: every model feature facing
// up under the pose should have query features within Delta: each one is
// seen or missed with the probabilities below. Bounded: the model's features
// x the query's features (<= max_features), for the kRefinedModels leaders.
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

bool near_query(const SearchContext& ctx, const Eigen::Vector3f& x) {
  const float* q = ctx.query.positions;
  for (uint32_t l = 0; l < ctx.query.count; ++l, q += 3) {
    const float dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
    if (dx * dx + dy * dy + dz * dz <= ctx.likelihood.delta2) return true;
  }
  return false;
}

}  // namespace

float upward_surface_log_likelihood(const SearchContext& ctx, uint32_t model, const RigidPose& pose) {
  const blob::ModelRecord& rec = ctx.db.model(model);
  float sum = 0.0f;
  for (uint32_t f = rec.first_feature; f < rec.first_feature + rec.feature_count; ++f) {
    const OrientedPoint m = ctx.model_point(f);
    if ((pose.rotation * m.n)[2] < kUpwardNormalZ) continue;
    sum += near_query(ctx, pose.rotation * m.p + pose.translation) ? kLogSeen : kLogMissed;
  }
  return sum;
}

}  // namespace spinhash
