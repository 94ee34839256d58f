// Internal interface (host tools may use it; not installed, may change):
// the database's quantised form of a spin image and the L1 distance between
// two quantised images, shared by the core, the database builder and the
// experiments so that all three compute the same numbers.
#pragma once
#include <cstdint>

namespace spinhash {

// q = min(255, round(v * scale)): the database's stored form of a spin image.
void quantize_spin(const float* image, uint32_t dims, float scale, uint8_t* out);

// L1 distance between two quantised spin images (exact integer: the same on every target).
inline uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  uint32_t sum = 0;
  for (uint32_t i = 0; i < dims; ++i) {
    int32_t d = static_cast<int32_t>(a[i]) - static_cast<int32_t>(b[i]);
    sum += static_cast<uint32_t>(d < 0 ? -d : d);
  }
  return sum;
}

// The L1 distance when it is at most `bound`; otherwise some partial sum
// above `bound` (the scan stops there: most database entries a query
// feature is compared with are far beyond the candidates it keeps). Blocks
// of a constant size compile to straight vector code; a block of 64 bytes
// is a cache line.
inline uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  constexpr uint32_t kBlock = 64;
  uint32_t sum = 0, i = 0;
  for (; i + kBlock <= dims; i += kBlock) {
    sum += l1_distance(a + i, b + i, kBlock);
    if (sum > bound) return sum;
  }
  return sum + l1_distance(a + i, b + i, dims - i);
}

}  // namespace spinhash
