// The portable scalar reference of the spin-image accumulation kernel: the
// definition every optimised kernel must reproduce bit for bit
// (tests/core/test_kernels.cpp). Targets without an optimised kernel
// (bare-metal Cortex-M, armhf, SPINHASH_KERNELS_REFERENCE) keep the grid
// walk of compute_spin_image, which runs the same arithmetic per neighbour.
#pragma once
#include <cstdint>

#include "kernels/spin_geometry.hpp"

namespace spinhash {
namespace kernels {
namespace reference {

// Adds to image the votes of g's points within the radius of the oriented
// point (p, n) that pass the support test, in g's order.
inline void spin_accumulate(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                            float* image) {
  for (uint32_t k = 0; k < g.count; ++k) spin_neighbour(b, g, k, p, n, image);
}

}  // namespace reference
}  // namespace kernels
}  // namespace spinhash
