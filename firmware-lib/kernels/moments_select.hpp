// The neighbour-moments kernel the normals use, chosen at compile time as
// the L1 and spin-image kernels are (kernels/l1_select.hpp,
// kernels/spin_select.hpp): SSE2 on x86-64, NEON on aarch64, else the
// portable reference (bare-metal Cortex-M, armhf).
// SPINHASH_KERNELS_REFERENCE forces the reference.
#pragma once
#include "kernels/moments_geometry.hpp"
#include "kernels/neon/moments.hpp"
#include "kernels/reference/moments.hpp"
#include "kernels/sse2/moments.hpp"

namespace spinhash {
namespace kernels {

#if defined(SPINHASH_KERNELS_REFERENCE)
namespace moments_selected = reference;
#elif defined(SPINHASH_KERNELS_HAVE_SSE2_MOMENTS)
namespace moments_selected = sse2;
#elif defined(SPINHASH_KERNELS_HAVE_NEON_MOMENTS)
namespace moments_selected = neon;
#else
namespace moments_selected = reference;
#endif

// Adds to m the offsets from q of g's points within sqrt(r2), in g's order.
inline void moments_accumulate(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  moments_selected::moments_accumulate(g, q, r2, m);
}

}  // namespace kernels
}  // namespace spinhash
