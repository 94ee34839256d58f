// The spin-image accumulation kernel the core uses, chosen at compile time
// as the L1 kernels are (kernels/l1_select.hpp): SSE2 on x86-64, NEON on
// aarch64, else the portable reference. SPINHASH_KERNELS_REFERENCE forces
// the reference. With the reference the core keeps compute_spin_image's
// grid walk (the same arithmetic, without gathered neighbourhoods: no code
// added to the bare-metal image).
#pragma once
#include "kernels/neon/spin.hpp"
#include "kernels/reference/spin.hpp"
#include "kernels/spin_geometry.hpp"
#include "kernels/sse2/spin.hpp"

namespace spinhash {
namespace kernels {

#if defined(SPINHASH_KERNELS_REFERENCE)
namespace spin_selected = reference;
constexpr bool kSpinGathers = false;
#elif defined(SPINHASH_KERNELS_HAVE_SSE2_SPIN)
namespace spin_selected = sse2;
constexpr bool kSpinGathers = true;
#elif defined(SPINHASH_KERNELS_HAVE_NEON_SPIN)
namespace spin_selected = neon;
constexpr bool kSpinGathers = true;
#else
namespace spin_selected = reference;
constexpr bool kSpinGathers = false;
#endif

inline void spin_accumulate(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                            float* image) {
  spin_selected::spin_accumulate(b, g, p, n, image);
}

}  // namespace kernels
}  // namespace spinhash
