#include "geometry/resample.hpp"

#include <cmath>

namespace spinhash {
namespace {

// The indices floor(i * n / keep), i = 0, 1, ..., of `keep` points spread
// evenly over n >= keep (all of them when keep == n), one after the other
// without a division per point: the quotient and remainder step by n's.
class EvenPicks {
 public:
  EvenPicks(uint32_t n, uint32_t keep) : step_(n / keep), rem_(n % keep), keep_(keep) {}
  uint32_t next() {
    const uint32_t at = q_;
    q_ += step_;
    r_ += rem_;
    if (r_ >= keep_) {
      r_ -= keep_;
      ++q_;
    }
    return at;
  }

 private:
  uint32_t step_, rem_, keep_, q_ = 0, r_ = 0;
};

// Farther than this from the frame origin a coordinate is garbage (Earth-centred
// coordinates stay below 7e6 m); such points are dropped like NaN so the
// double mean and the float offsets cannot overflow.
constexpr double kMaxCoordinate = 1e9;

template <typename T>
bool usable(const T* p) {
  for (int a = 0; a < 3; ++a)
    if (!(std::fabs(static_cast<double>(p[a])) <= kMaxCoordinate)) return false;  // false for NaN too
  return true;
}

template <typename T>
uint32_t recentre_typed(const T* xyz, uint32_t n, uint32_t keep, double origin[3], float* out) {
  double sum[3] = {0.0, 0.0, 0.0};
  uint32_t finite = 0;
  EvenPicks sum_picks(n, keep);
  for (uint32_t i = 0; i < keep; ++i) {
    const T* p = xyz + 3u * sum_picks.next();
    if (!usable(p)) continue;
    for (int a = 0; a < 3; ++a) sum[a] += static_cast<double>(p[a]);
    ++finite;
  }
  for (int a = 0; a < 3; ++a) origin[a] = finite > 0 ? sum[a] / finite : 0.0;
  const bool all_usable = finite == keep;  // the second pass need not test again
  uint32_t k = 0;
  EvenPicks out_picks(n, keep);
  for (uint32_t i = 0; i < keep; ++i) {
    const T* p = xyz + 3u * out_picks.next();
    if (!all_usable && !usable(p)) continue;
    for (int a = 0; a < 3; ++a) out[3u * k + a] = static_cast<float>(static_cast<double>(p[a]) - origin[a]);
    ++k;
  }
  return k;
}

}  // namespace

uint32_t recentre(const CloudView& cloud, uint32_t keep, double origin[3], float* out) {
  if (keep > cloud.count) keep = cloud.count;
  if (keep == 0) return 0;
  if (cloud.xyz_d != nullptr) return recentre_typed(cloud.xyz_d, cloud.count, keep, origin, out);
  return recentre_typed(cloud.xyz_f, cloud.count, keep, origin, out);
}

uint32_t equalise_density(const CellGrid& grid, const float* points, float* out) {
  const uint32_t* order = grid.order();
  for (uint32_t c = 0; c < grid.cell_count(); ++c) {
    float s[3] = {0.0f, 0.0f, 0.0f};
    uint32_t first = grid.cell_first(c), count = grid.cell_size_of(c);
    for (uint32_t k = 0; k < count; ++k)
      for (int a = 0; a < 3; ++a) s[a] += points[3u * order[first + k] + a];
    for (int a = 0; a < 3; ++a) out[3u * c + a] = s[a] / static_cast<float>(count);
  }
  return grid.cell_count();
}

uint32_t select_basis_points(const CellGrid& grid, const float* points, const uint8_t* has_normal,
                             uint32_t* out) {
  const uint32_t* order = grid.order();
  uint32_t chosen = 0;
  for (uint32_t c = 0; c < grid.cell_count(); ++c) {
    uint32_t first = grid.cell_first(c), count = grid.cell_size_of(c);
    float s[3] = {0.0f, 0.0f, 0.0f};
    uint32_t oriented = 0;
    for (uint32_t k = 0; k < count; ++k) {
      uint32_t i = order[first + k];
      if (!has_normal[i]) continue;
      for (int a = 0; a < 3; ++a) s[a] += points[3u * i + a];
      ++oriented;
    }
    if (oriented == 0) continue;
    for (int a = 0; a < 3; ++a) s[a] /= static_cast<float>(oriented);
    uint32_t best = 0;
    float best_d2 = 3.4e38f;
    for (uint32_t k = 0; k < count; ++k) {
      uint32_t i = order[first + k];
      if (!has_normal[i]) continue;
      const float* p = points + 3u * i;
      float d2 =
          (p[0] - s[0]) * (p[0] - s[0]) + (p[1] - s[1]) * (p[1] - s[1]) + (p[2] - s[2]) * (p[2] - s[2]);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = i;
      }
    }
    out[chosen++] = best;
  }
  return chosen;
}

uint32_t thin_evenly(uint32_t* indices, uint32_t n, uint32_t keep) {
  if (n <= keep) return n;
  for (uint32_t j = 0; j < keep; ++j)
    indices[j] = indices[static_cast<uint64_t>(j) * n / keep];  // j*n/keep >= j: in-place safe
  return keep;
}

}  // namespace spinhash
