#include "match/likelihood.hpp"

#include <cmath>

#include "util/fixed_math.hpp"

namespace spinhash {
namespace {

constexpr float kMaxNormalisedL1 = 2.0f;  // L1 between two sum-1 histograms

struct Nearest {
  int64_t feature = -1;
  float dist2 = 0.0f;
};

// Nearest model feature to x (model frame) within Delta_max whose normal agrees.
Nearest nearest_model_feature(const Database& db, const blob::ModelRecord& rec,
                              const Eigen::Vector3f& x, const Eigen::Vector3f& n,
                              const LikelihoodParams& lp) {
  Nearest best;
  best.dist2 = lp.delta_max2;
  const float cell = db.params().grid_cell;
  int32_t c[3];
  for (int a = 0; a < 3; ++a) c[a] = static_cast<int32_t>(std::floor((x[a] - rec.grid_origin[a]) / cell));
  const int32_t r = static_cast<int32_t>(lp.reach);
  const int32_t dx = static_cast<int32_t>(rec.grid_dims[0]), dy = static_cast<int32_t>(rec.grid_dims[1]),
                dz = static_cast<int32_t>(rec.grid_dims[2]);
  const uint32_t* offsets = db.grid_offsets() + rec.grid_offset_base;
  const float* pos = db.positions();
  const int16_t* nrm = db.normals();
  for (int32_t z = c[2] - r; z <= c[2] + r; ++z) {
    if (z < 0 || z >= dz) continue;
    for (int32_t y = c[1] - r; y <= c[1] + r; ++y) {
      if (y < 0 || y >= dy) continue;
      for (int32_t xx = c[0] - r; xx <= c[0] + r; ++xx) {
        if (xx < 0 || xx >= dx) continue;
        uint32_t cell_index = static_cast<uint32_t>(xx + dx * (y + dy * z));
        uint32_t end = rec.first_feature + offsets[cell_index + 1u];
        for (uint32_t f = rec.first_feature + offsets[cell_index]; f < end; ++f) {
          const float* p = pos + 3u * f;
          float ex = p[0] - x[0], ey = p[1] - x[1], ez = p[2] - x[2];
          float d2 = ex * ex + ey * ey + ez * ez;
          if (d2 >= best.dist2) continue;
          const int16_t* m = nrm + 3u * f;
          float dot = (static_cast<float>(m[0]) * n[0] + static_cast<float>(m[1]) * n[1] +
                       static_cast<float>(m[2]) * n[2]) * (1.0f / 32767.0f);
          if (dot < lp.cos_eta_max) continue;
          best.dist2 = d2;
          best.feature = f;
        }
      }
    }
  }
  return best;
}

}  // namespace

LikelihoodParams make_likelihood_params(const RecognizerConfig& cfg, const Database& db) {
  LikelihoodParams lp;
  lp.inv_two_sigma2 = 1.0f / (2.0f * cfg.sigma * cfg.sigma);
  lp.delta2 = cfg.delta * cfg.delta;
  lp.delta_max2 = cfg.delta_max * cfg.delta_max;
  lp.cos_eta_max = std::cos(deg_to_rad(cfg.eta_max_deg));
  lp.spin_weight = 1.0f / (cfg.spin_lambda * db.params().spin_quant_scale);
  lp.floor = -lp.delta2 * lp.inv_two_sigma2 - kMaxNormalisedL1 / cfg.spin_lambda;
  lp.reach = static_cast<uint32_t>(std::ceil(cfg.delta_max / db.params().grid_cell));
  return lp;
}

namespace {

// A stride coprime with n visits 0..n-1 once each, spread over the query.
uint32_t spread_stride(uint32_t n) {
  const uint32_t kCandidates[] = {7919u, 104729u, 1299709u, 15485863u};  // primes
  for (uint32_t p : kCandidates)
    if (n % p != 0u) return p % n;
  return 1u;
}

}  // namespace

Verification verify_pose(const Database& db, uint32_t model, const RigidPose& pose,
                         const QueryFeatures& query, const LikelihoodParams& lp, float to_beat,
                         bool preemptive) {
  Verification v;
  const blob::ModelRecord& rec = db.model(model);
  const Eigen::Matrix3f rt = pose.rotation.transpose();
  const uint32_t n = query.count;
  const uint32_t stride = n > 1u ? spread_stride(n) : 1u;
  const float best_mean = to_beat / static_cast<float>(n > 0u ? n : 1u);
  uint32_t l = 0;
  for (uint32_t i = 0; i < n; ++i, l = (l + stride) % n) {
    if (v.log_likelihood < to_beat) return v;  // remaining terms are <= 0
    if (preemptive && i == kPreemptiveFeatures && i < n &&
        v.log_likelihood / static_cast<float>(i) < best_mean - kPreemptiveSlack)
      return v;
    Eigen::Vector3f qp(query.positions[3u * l], query.positions[3u * l + 1u], query.positions[3u * l + 2u]);
    Eigen::Vector3f qn(query.normals[3u * l], query.normals[3u * l + 1u], query.normals[3u * l + 2u]);
    Eigen::Vector3f x = rt * (qp - pose.translation);
    Eigen::Vector3f nm = rt * qn;
    Nearest near = nearest_model_feature(db, rec, x, nm, lp);
    if (near.feature < 0) {
      v.log_likelihood += lp.floor;
      continue;
    }
    float r2 = near.dist2 < lp.delta2 ? near.dist2 : lp.delta2;
    uint32_t l1 = l1_distance(query.spins + static_cast<size_t>(l) * query.dims,
                              db.spin(static_cast<uint32_t>(near.feature)), query.dims);
    float term = -r2 * lp.inv_two_sigma2 - static_cast<float>(l1) * lp.spin_weight;
    v.log_likelihood += term > lp.floor ? term : lp.floor;
    v.inliers += near.dist2 <= lp.delta2 ? 1u : 0u;
  }
  v.complete = true;
  return v;
}

}  // namespace spinhash
