// Every neighbour-moments kernel this build holds, out of line and compiled
// with the core's flags (-ffp-contract=off), for the kernel tests
// (tests/core/test_moments_kernels.cpp). The core itself inlines the
// selected one.
#pragma once
#include "kernels/moments_select.hpp"

namespace spinhash {
namespace kernels {

using MomentsAccumulate = void (*)(const MomentsNeighbours&, const float*, float, NeighbourMoments*);

void moments_accumulate_reference(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m);
#if defined(SPINHASH_KERNELS_HAVE_SSE2_MOMENTS)
void moments_accumulate_sse2(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m);
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_MOMENTS)
void moments_accumulate_neon(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m);
#endif
void moments_accumulate_selected(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m);

}  // namespace kernels
}  // namespace spinhash
