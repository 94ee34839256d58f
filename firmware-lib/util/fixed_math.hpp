// Small numeric helpers shared by the core.
#pragma once
#include <cmath>
#include <cstdint>

#include "spinhash/internal/spin_quantize.hpp"  // l1_distance

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

}  // namespace spinhash
