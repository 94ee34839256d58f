// The L1 kernels the core uses, chosen at compile time as Eigen's arch/
// folders are: AVX2 when the build targets it, else SSE2 on x86-64, NEON on
// aarch64 (and armhf built with NEON), else the portable reference (the
// bare-metal Cortex-M build). SPINHASH_KERNELS_REFERENCE (a CMake option)
// forces the reference. Inline here for the core's hot loops; host code
// calls the same kernel through include/spinhash/internal/l1_distance.hpp.
#pragma once
#include <cstdint>

#include "kernels/avx2/l1.hpp"
#include "kernels/neon/l1.hpp"
#include "kernels/reference/l1.hpp"
#include "kernels/sse2/l1.hpp"

namespace spinhash {
namespace kernels {

#if defined(SPINHASH_KERNELS_REFERENCE)
namespace selected = reference;
#elif defined(__AVX2__) && defined(SPINHASH_KERNELS_HAVE_AVX2)
namespace selected = avx2;
#elif defined(SPINHASH_KERNELS_HAVE_SSE2)
namespace selected = sse2;
#elif defined(SPINHASH_KERNELS_HAVE_NEON)
namespace selected = neon;
#else
namespace selected = reference;
#endif

// Exact sum of |a[i] - b[i]| over dims bytes (the same integer on every target).
inline uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  return selected::l1_distance(a, b, dims);
}

// The L1 distance when it is at most `bound`; otherwise some partial sum
// above `bound` (the scan stops there: most database entries a query
// feature is compared with are far beyond the candidates it keeps). The
// candidate search depends on exactly this contract.
inline uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  return selected::l1_distance_within(a, b, dims, bound);
}

}  // namespace kernels
}  // namespace spinhash
