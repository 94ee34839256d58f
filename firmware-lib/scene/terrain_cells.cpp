#include "scene/terrain_cells.hpp"

#include <cmath>

namespace spinhash {

void TerrainCells::carve(Arena& arena, double cell_m, double depth, double width) {
  cell = cell_m;
  along = static_cast<uint32_t>(std::ceil(depth / cell_m)) + 2u;
  across = static_cast<uint32_t>(std::ceil(width / cell_m)) + 2u;
  const size_t n = static_cast<size_t>(along) * across;
  lowest = arena.alloc<float>(n);
  band_sum = arena.alloc<float>(n);
  band_count = arena.alloc<float>(n);
}

int64_t TerrainCells::index_along(double s) const { return static_cast<int64_t>(std::floor(s / cell)); }

uint32_t TerrainCells::slot(int64_t i, uint32_t it) const {
  const int64_t a = static_cast<int64_t>(along);
  const uint32_t row = static_cast<uint32_t>(((i % a) + a) % a);
  return row * across + it;
}

namespace {

// Calls f(slot, z) for each ring point in cells [i0, i1) along and within
// the slots across, in the ring's (arrival) order.
template <class F>
void for_cell_points(const TerrainCells& tc, const PointRing& ring, int64_t i0, int64_t i1, F&& f) {
  const double s0 = static_cast<double>(i0) * tc.cell, s1 = static_cast<double>(i1) * tc.cell;
  for (uint32_t k = 0; k < ring.count; ++k) {
    double p[3];
    ring.get(k, p);
    if (p[0] < s0 || p[0] >= s1) continue;
    const double t = std::floor((p[1] - tc.t_min) / tc.cell);
    if (t < 0.0 || t >= static_cast<double>(tc.across)) continue;
    f(tc.index_along(p[0]), static_cast<uint32_t>(t), static_cast<float>(p[2]));
  }
}

}  // namespace

void TerrainCells::sum(const PointRing& ring, double from_s, double to_s) {
  int64_t i0 = index_along(from_s);
  const int64_t i1 = index_along(to_s);
  if (started && summed_to > i0) i0 = summed_to;
  if (i1 - i0 > static_cast<int64_t>(along)) i0 = i1 - static_cast<int64_t>(along);  // older cells are gone
  for (int64_t i = i0; i < i1; ++i)
    for (uint32_t it = 0; it < across; ++it) {
      const uint32_t c = slot(i, it);
      lowest[c] = NAN;
      band_sum[c] = 0.0f;
      band_count[c] = 0.0f;
    }
  for_cell_points(*this, ring, i0, i1,
                  [&](int64_t i, uint32_t it, float z) { terrain_lowest(lowest[slot(i, it)], z); });
  for_cell_points(*this, ring, i0, i1, [&](int64_t i, uint32_t it, float z) {
    const uint32_t c = slot(i, it);
    terrain_low_band(lowest[c], z, band_sum[c], band_count[c]);
  });
  if (!started || i1 > summed_to) summed_to = i1;
  started = true;
}

Status TerrainCells::fill(const FrameRect& rect, double s0, double t0, float cell_m,
                          TerrainGrid& grid) const {
  const int64_t i0 = index_along(rect.s0), i1 = index_along(rect.s1);
  const double t_lo = std::floor((rect.t0 - t_min) / cell), t_hi = std::ceil((rect.t1 - t_min) / cell);
  const uint32_t j0 = t_lo < 0.0 ? 0u : static_cast<uint32_t>(t_lo);
  const uint32_t j1 = t_hi > static_cast<double>(across) ? across : static_cast<uint32_t>(t_hi);
  // The footprint of the cells that hold points, as the grid over the
  // points' own bounds would have it.
  int64_t lo_i = i1, hi_i = i0 - 1;
  uint32_t lo_j = j1, hi_j = 0;
  for (int64_t i = i0; i < i1; ++i)
    for (uint32_t j = j0; j < j1; ++j) {
      if (std::isnan(lowest[slot(i, j)])) continue;
      lo_i = i < lo_i ? i : lo_i;
      hi_i = i > hi_i ? i : hi_i;
      lo_j = j < lo_j ? j : lo_j;
      hi_j = j > hi_j ? j : hi_j;
    }
  if (hi_i < lo_i) return Status::kEmptyCloud;
  const float x0 = static_cast<float>(static_cast<double>(lo_i) * cell - s0);
  const float y0 = static_cast<float>(t_min + static_cast<double>(lo_j) * cell - t0);
  const uint32_t nx = static_cast<uint32_t>(hi_i - lo_i + 1), ny = hi_j - lo_j + 1u;
  if (!terrain_begin_cells(grid, cell_m, x0, y0, nx, ny)) return Status::kTileTooLarge;
  for (int64_t i = lo_i; i <= hi_i; ++i)
    for (uint32_t j = lo_j; j <= hi_j; ++j) {
      const uint32_t c = slot(i, j);
      if (!std::isnan(lowest[c]))
        terrain_put_cell(grid, static_cast<uint32_t>(i - lo_i), j - lo_j, lowest[c], band_sum[c],
                         band_count[c]);
    }
  return Status::kOk;
}

}  // namespace spinhash
