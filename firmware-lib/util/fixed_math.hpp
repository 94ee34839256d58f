// Small numeric helpers shared by the core.
#pragma once
#include <cmath>
#include <cstdint>

namespace spinhash {

constexpr float kPi = 3.14159265358979323846f;
inline float deg_to_rad(float deg) { return deg * (kPi / 180.0f); }
inline float clampf(float v, float lo, float hi) { return v < lo ? lo : (v > hi ? hi : v); }
inline float safe_acos(float c) { return std::acos(clampf(c, -1.0f, 1.0f)); }
inline uint32_t next_pow2(uint32_t v) {
  uint32_t p = 1u;
  while (p < v && p < 0x80000000u) p <<= 1u;  // bounded: at most 31 doublings
  return p;
}
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
