// The portable scalar reference of the neighbour-moments kernel: the
// definition every optimised kernel must reproduce bit for bit
// (tests/core/test_moments_kernels.cpp), and the kernel of targets without
// one (bare-metal Cortex-M, armhf, SPINHASH_KERNELS_REFERENCE).
#pragma once
#include <cstdint>

#include "kernels/moments_geometry.hpp"

namespace spinhash {
namespace kernels {
namespace reference {

// Adds to m the offsets from q of g's points within sqrt(r2), in g's order.
inline void moments_accumulate(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  for (uint32_t k = 0; k < g.count; ++k) moments_neighbour(g, k, q, r2, m);
}

}  // namespace reference
}  // namespace kernels
}  // namespace spinhash
