#include "recognize/sparse_search.hpp"

#include <cmath>

#include "recognize/confidence.hpp"

namespace spinhash {

float footprint_density(const QueryFeatures& query, uint32_t points) {
  if (query.count == 0) return 0.0f;
  const float n = static_cast<float>(query.count);
  float mx = 0.0f, my = 0.0f;
  for (uint32_t f = 0; f < query.count; ++f)
    mx += query.positions[3u * f], my += query.positions[3u * f + 1u];
  mx /= n, my /= n;
  float sxx = 0.0f, sxy = 0.0f, syy = 0.0f;
  for (uint32_t f = 0; f < query.count; ++f) {
    const float dx = query.positions[3u * f] - mx, dy = query.positions[3u * f + 1u] - my;
    sxx += dx * dx, sxy += dx * dy, syy += dy * dy;
  }
  const float angle = 0.5f * std::atan2(2.0f * sxy, sxx - syy);
  const float c = std::cos(angle), s = std::sin(angle);
  float ulo = 0.0f, uhi = 0.0f, vlo = 0.0f, vhi = 0.0f;
  for (uint32_t f = 0; f < query.count; ++f) {
    const float dx = query.positions[3u * f] - mx, dy = query.positions[3u * f + 1u] - my;
    const float u = c * dx + s * dy, v = c * dy - s * dx;
    ulo = u < ulo ? u : ulo, uhi = u > uhi ? u : uhi;
    vlo = v < vlo ? v : vlo, vhi = v > vhi ? v : vhi;
  }
  const float area = (uhi - ulo) * (vhi - vlo);
  return static_cast<float>(points) / (area > kMinFootprint ? area : kMinFootprint);
}

uint32_t trial_scale(float density) { return dense_enough_for_model(density) ? 1u : kSparseTrialScale; }

uint32_t sparse_bucket_scan(uint32_t max_bucket_scan) {
  if (max_bucket_scan >= kMaxSparseBucketScan / kSparseScanScale)
    return max_bucket_scan > kMaxSparseBucketScan ? max_bucket_scan : kMaxSparseBucketScan;
  return max_bucket_scan * kSparseScanScale;
}

uint32_t bucket_scan(uint32_t max_bucket_scan, uint32_t max_features, float density, uint32_t features) {
  if (dense_enough_for_model(density) || features == 0) return max_bucket_scan;
  const uint64_t share = static_cast<uint64_t>(max_features) * max_bucket_scan / features;
  const uint32_t scan = sparse_bucket_scan(max_bucket_scan);
  if (share >= scan) return scan;
  return share > max_bucket_scan ? static_cast<uint32_t>(share) : max_bucket_scan;
}

}  // namespace spinhash
