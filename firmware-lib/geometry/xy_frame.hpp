// The xy frame of a per-cell grid laid over a cloud's footprint (the terrain
// grid, the segmentation grid): origin at the footprint's min corner snapped
// down to a multiple of the cell, square cells, refused when the footprint
// needs more cells than were carved. The snap makes the grids of two scene
// windows whose origins differ by a multiple of the cell share their cells.
#pragma once
#include <cmath>
#include <cstdint>

namespace spinhash {

// The grid over the footprint [lo, hi] (x, y): its min corner snapped down
// to a multiple of the cell; false when it needs more than max_cells.
template <class Grid>
bool fit_xy_bounds(const float* lo, const float* hi, float cell, Grid& g) {
  const float x0 = std::floor(lo[0] / cell) * cell, y0 = std::floor(lo[1] / cell) * cell;
  const float fx = (hi[0] - x0) / cell + 1.0f, fy = (hi[1] - y0) / cell + 1.0f;
  if (!(fx * fy <= static_cast<float>(g.max_cells))) return false;
  g.cell = cell;
  g.x0 = x0;
  g.y0 = y0;
  g.nx = static_cast<uint32_t>(fx);
  g.ny = static_cast<uint32_t>(fy);
  return true;
}

// The x, y bounds of n xyz points (n > 0).
inline void xy_bounds(const float* xyz, uint32_t n, float* lo, float* hi) {
  lo[0] = hi[0] = xyz[0];
  lo[1] = hi[1] = xyz[1];
  for (uint32_t i = 1; i < n; ++i)
    for (uint32_t a = 0; a < 2u; ++a) {
      const float v = xyz[3u * i + a];
      lo[a] = v < lo[a] ? v : lo[a];
      hi[a] = v > hi[a] ? v : hi[a];
    }
}

// Min corner and size in cells of `n` xyz points' footprint at cells of
// `cell` m; false when that exceeds `max_cells` (the tile is too large for
// the workspace: never truncated). n > 0.
template <class Grid>
bool fit_xy_frame(const float* xyz, uint32_t n, float cell, Grid& g) {
  float lo[2], hi[2];
  xy_bounds(xyz, n, lo, hi);
  return fit_xy_bounds(lo, hi, cell, g);
}

}  // namespace spinhash
