// Internal interface (host tools may use it; not installed, may change):
// the database's quantised form of a spin image and the L1 distance between
// two quantised images, shared by the core, the database builder and the
// experiments so that all three compute the same numbers.
#pragma once
#include <cstdint>

namespace spinhash {

// q = min(255, round(v * scale)): the database's stored form of a spin image.
void quantize_spin(const float* image, uint32_t dims, float scale, uint8_t* out);

namespace detail {

// Sum of |a[i] - b[i]| over n bytes. Called with constant n, it compiles to
// straight vector code (a byte-wise absolute-difference sum).
inline uint32_t l1_bytes(const uint8_t* a, const uint8_t* b, uint32_t n) {
  uint32_t sum = 0;
  for (uint32_t i = 0; i < n; ++i) {
    int32_t d = static_cast<int32_t>(a[i]) - static_cast<int32_t>(b[i]);
    sum += static_cast<uint32_t>(d < 0 ? -d : d);
  }
  return sum;
}

// The bytes [i, dims) after whole 64-byte blocks, in constant blocks of 32
// and 4 bytes: a runtime-length loop over 36 bytes (the 10 x 10 image's
// tail) costs about three times the instructions of these blocks.
inline uint32_t l1_tail(const uint8_t* a, const uint8_t* b, uint32_t i, uint32_t dims) {
  uint32_t sum = 0;
  if (i + 32u <= dims) {
    sum += l1_bytes(a + i, b + i, 32u);
    i += 32u;
  }
  for (; i + 4u <= dims; i += 4u) sum += l1_bytes(a + i, b + i, 4u);
  for (; i < dims; ++i) sum += l1_bytes(a + i, b + i, 1u);
  return sum;
}

constexpr uint32_t kL1Block = 64;  // bytes per early-exit check: a cache line

}  // namespace detail

// L1 distance between two quantised spin images (exact integer: the same on every target).
inline uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  uint32_t sum = 0, i = 0;
  for (; i + detail::kL1Block <= dims; i += detail::kL1Block)
    sum += detail::l1_bytes(a + i, b + i, detail::kL1Block);
  return sum + detail::l1_tail(a, b, i, dims);
}

// The L1 distance when it is at most `bound`; otherwise some partial sum
// above `bound` (the scan stops there: most database entries a query
// feature is compared with are far beyond the candidates it keeps).
inline uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  uint32_t sum = 0, i = 0;
  for (; i + detail::kL1Block <= dims; i += detail::kL1Block) {
    sum += detail::l1_bytes(a + i, b + i, detail::kL1Block);
    if (sum > bound) return sum;
  }
  return sum + detail::l1_tail(a, b, i, dims);
}

}  // namespace spinhash
