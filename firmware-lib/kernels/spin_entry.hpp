// Every spin-image accumulation kernel this build holds, out of line and
// compiled with the core's flags (-ffp-contract=off), for the kernel tests
// (tests/core/test_kernels.cpp). The core itself inlines the selected one.
#pragma once
#include "kernels/spin_select.hpp"

namespace spinhash {
namespace kernels {

using SpinAccumulate = void (*)(const SpinGeometry&, const SpinNeighbours&, const float*, const float*,
                                float*);

void spin_accumulate_reference(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                               float* image);
#if defined(SPINHASH_KERNELS_HAVE_SSE2_SPIN)
void spin_accumulate_sse2(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                          float* image);
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_SPIN)
void spin_accumulate_neon(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                          float* image);
#endif
void spin_accumulate_selected(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                              float* image);

}  // namespace kernels
}  // namespace spinhash
