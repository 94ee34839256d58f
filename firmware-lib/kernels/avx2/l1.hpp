// AVX2 L1 kernels: vpsadbw on 32 bytes at a time. Selected when the build
// targets AVX2 (-mavx2, -march=x86-64-v3); otherwise built with the avx2
// target attribute so that the kernel test runs them on a CPU that has it.
#pragma once
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include <cstdint>

#include "kernels/l1_blocks.hpp"
#include "kernels/sse2/l1.hpp"

#define SPINHASH_KERNELS_HAVE_AVX2 1
#if defined(__AVX2__)
#define SPINHASH_AVX2_INLINE inline
#else
#define SPINHASH_AVX2_INLINE __attribute__((target("avx2"))) inline
#endif

namespace spinhash {
namespace kernels {
namespace avx2 {

constexpr const char* kName = "avx2";

SPINHASH_AVX2_INLINE uint32_t sad(const uint8_t* a, const uint8_t* b, uint32_t n) {
  __m256i wide = _mm256_setzero_si256();
  uint32_t i = 0;
  for (; i + 32u <= n; i += 32u) {
    const __m256i va = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + i));
    const __m256i vb = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + i));
    wide = _mm256_add_epi64(wide, _mm256_sad_epu8(va, vb));
  }
  __m128i acc = _mm_add_epi64(_mm256_castsi256_si128(wide), _mm256_extracti128_si256(wide, 1));
  if (i + 16u <= n) {
    const __m128i va = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + i));
    const __m128i vb = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + i));
    acc = _mm_add_epi64(acc, _mm_sad_epu8(va, vb));
    i += 16u;
  }
  return sse2::horizontal_sum(acc) + sse2::sad(a + i, b + i, n - i);
}

SPINHASH_AVX2_INLINE uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  return distance_paper_first<sad>(a, b, dims);
}

SPINHASH_AVX2_INLINE uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims,
                                                 uint32_t bound) {
  return within_paper_first<sad>(a, b, dims, bound);
}

}  // namespace avx2
}  // namespace kernels
}  // namespace spinhash
#endif  // x86-64, GCC or Clang
