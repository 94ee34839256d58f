// SSE2 L1 kernels (every x86-64 CPU): psadbw sums the absolute differences
// of 8 byte pairs into each 64-bit half of a register.
#pragma once
#if defined(__SSE2__)
#include <emmintrin.h>

#include <cstdint>
#include <cstring>

#include "kernels/l1_blocks.hpp"
#include "kernels/reference/l1.hpp"

#define SPINHASH_KERNELS_HAVE_SSE2 1

namespace spinhash {
namespace kernels {
namespace sse2 {

constexpr const char* kName = "sse2";

// The two 64-bit halves' sums; each is at most 255 * n / 2, within 32 bits for any image.
inline uint32_t horizontal_sum(__m128i acc) {
  return static_cast<uint32_t>(_mm_cvtsi128_si32(acc)) +
         static_cast<uint32_t>(_mm_cvtsi128_si32(_mm_unpackhi_epi64(acc, acc)));
}

// Loads of 8 and 4 bytes: never past the image's end (it may end a blob).
inline __m128i load8(const uint8_t* p) { return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)); }
inline __m128i load4(const uint8_t* p) {
  int32_t v;
  std::memcpy(&v, p, sizeof v);
  return _mm_cvtsi32_si128(v);
}

inline uint32_t sad(const uint8_t* a, const uint8_t* b, uint32_t n) {
  __m128i acc = _mm_setzero_si128();
  uint32_t i = 0;
  for (; i + 16u <= n; i += 16u) {
    const __m128i va = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + i));
    const __m128i vb = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + i));
    acc = _mm_add_epi64(acc, _mm_sad_epu8(va, vb));
  }
  if (i + 8u <= n) {
    acc = _mm_add_epi64(acc, _mm_sad_epu8(load8(a + i), load8(b + i)));
    i += 8u;
  }
  if (i + 4u <= n) {
    acc = _mm_add_epi64(acc, _mm_sad_epu8(load4(a + i), load4(b + i)));
    i += 4u;
  }
  return horizontal_sum(acc) + reference::sad(a + i, b + i, n - i);
}

inline uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  return distance_paper_first<sad>(a, b, dims);
}

inline uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  return within_paper_first<sad>(a, b, dims, bound);
}

}  // namespace sse2
}  // namespace kernels
}  // namespace spinhash
#endif  // __SSE2__
