#include "geometry/ground.hpp"

namespace spinhash {
namespace {

// Height below which `share` of the points lie, to within one histogram bin.
float percentile_height(const float* xyz, uint32_t n, float z_lo, float z_hi, float share,
                        uint32_t* histogram) {
  for (uint32_t b = 0; b < kGroundHistogramBins; ++b) histogram[b] = 0;
  const float scale = static_cast<float>(kGroundHistogramBins) / (z_hi - z_lo);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t b = static_cast<uint32_t>((xyz[3u * i + 2u] - z_lo) * scale);  // z_lo <= z <= z_hi: no overflow
    ++histogram[b < kGroundHistogramBins ? b : kGroundHistogramBins - 1u];
  }
  const float wanted = share * static_cast<float>(n);
  uint32_t below = 0;
  for (uint32_t b = 0; b < kGroundHistogramBins; ++b) {
    below += histogram[b];
    if (static_cast<float>(below) >= wanted) return z_lo + static_cast<float>(b + 1u) / scale;
  }
  return z_hi;
}

}  // namespace

uint32_t remove_level_ground(float* xyz, uint32_t n, float clearance, uint32_t* histogram) {
  if (n == 0 || !(clearance > 0.0f)) return 0;
  float z_lo = xyz[2], z_hi = xyz[2];
  for (uint32_t i = 1; i < n; ++i) {
    const float z = xyz[3u * i + 2u];
    z_lo = z < z_lo ? z : z_lo;
    z_hi = z > z_hi ? z : z_hi;
  }
  if (!(z_hi - z_lo > clearance)) return 0;  // all within one slab: nothing stands on a ground
  const float top = percentile_height(xyz, n, z_lo, z_hi, kGroundPercentile, histogram) + clearance;
  uint32_t in_slab = 0;
  for (uint32_t i = 0; i < n; ++i) in_slab += xyz[3u * i + 2u] <= top ? 1u : 0u;
  if (static_cast<float>(in_slab) < kMinGroundShare * static_cast<float>(n)) return 0;
  uint32_t kept = 0;
  for (uint32_t i = 0; i < n; ++i) {
    if (xyz[3u * i + 2u] <= top) continue;
    for (uint32_t a = 0; a < 3u; ++a) xyz[3u * kept + a] = xyz[3u * i + a];
    ++kept;
  }
  return n - kept;
}

}  // namespace spinhash
