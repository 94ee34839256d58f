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

}  // namespace spinhash
