#include "recognize/confidence.hpp"

namespace spinhash {
namespace {

// Box faces tested: both ends along x and y, and the top (z up in the model).
constexpr int kTestedFaces = 5;

}  // namespace

ExtentFit extent_fit(const QueryFeatures& query, const blob::ModelRecord& model, const RigidPose& pose) {
  ExtentFit fit;
  if (query.count == 0) return fit;
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(3.0e38f), hi = -lo;
  const Eigen::Matrix3f to_model = pose.rotation.transpose();
  for (uint32_t f = 0; f < query.count; ++f) {
    const Eigen::Vector3f x =
        to_model * (Eigen::Map<const Eigen::Vector3f>(query.positions + 3u * f) - pose.translation);
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  // Per face, how far the query stops short of it (> 0) or reaches past it (< 0).
  const float gap[kTestedFaces] = {lo[0] - model.bbox_min[0], model.bbox_max[0] - hi[0],
                                   lo[1] - model.bbox_min[1], model.bbox_max[1] - hi[1],
                                   model.bbox_max[2] - hi[2]};
  for (float g : gap) {
    fit.shortfall = g > fit.shortfall ? g : fit.shortfall;
    fit.overhang = -g > fit.overhang ? -g : fit.overhang;
  }
  return fit;
}

uint32_t lookalike_group_size(const Result& r, const RecognizerConfig& cfg, uint32_t features) {
  if (r.ranking_count == 0) return 0;
  if (cfg.mode == Mode::kSind) return 1;
  const float within = cfg.min_margin * static_cast<float>(features);
  uint32_t k = 1;
  while (k < r.ranking_count && r.ranking[0].score - r.ranking[k].score < within) ++k;
  return k;
}

bool is_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit) {
  if (r.ranking_count == 0 || !r.ranking[0].has_pose) return false;
  const float n = static_cast<float>(features);
  return static_cast<float>(r.ranking[0].inliers) >= cfg.min_inlier_fraction * n &&
         r.ranking[0].score >= cfg.min_mean_log_likelihood * n && r.group_size == 1u &&
         fit.shortfall <= cfg.max_extent_shortfall && fit.overhang <= cfg.max_extent_overhang;
}

}  // namespace spinhash
