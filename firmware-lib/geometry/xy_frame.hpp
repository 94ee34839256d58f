// The xy frame of a per-cell grid laid over a cloud's footprint (the
// segmentation grid): its origin at the footprint's min corner snapped down
// to a multiple of the cell, so that the grids of two scene windows whose
// origins differ by a multiple of the cell share their cells.
#pragma once
#include <cmath>
#include <cstdint>

namespace spinhash {

// v snapped down to a multiple of the cell.
inline float snap_down(float v, float cell) { return std::floor(v / cell) * cell; }

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

}  // namespace spinhash
