#include "recognize/sparse_search.hpp"

#include <cmath>

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

bool searched_as_sparse(const StageParams& p, float density) {
  return !(density >= p.candidates.sparse_density);
}

uint32_t trial_scale(const StageParams& p, float density) {
  return searched_as_sparse(p, density) ? p.draws.sparse_trial_scale : 1u;
}

uint32_t sparse_bucket_scan(const CandidatesParams& p) {
  const uint32_t scan = p.max_bucket_scan, most = p.max_sparse_bucket_scan;
  if (scan >= most / p.sparse_scan_scale) return scan > most ? scan : most;
  return scan * p.sparse_scan_scale;
}

uint32_t bucket_scan(const StageParams& p, uint32_t max_features, float density, uint32_t features) {
  const uint32_t scan = p.candidates.max_bucket_scan;
  if (!searched_as_sparse(p, density) || features == 0) return scan;
  const uint64_t share = static_cast<uint64_t>(max_features) * scan / features;
  const uint32_t sparse = sparse_bucket_scan(p.candidates);
  if (share >= sparse) return sparse;
  return share > scan ? static_cast<uint32_t>(share) : scan;
}

}  // namespace spinhash
