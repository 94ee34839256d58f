// Angles and clamps of the core, in float: degrees to radians and back, and
// an acos that tolerates rounding just outside [-1, 1].
#pragma once
#include <cmath>

namespace spinhash {

constexpr float kPi = 3.14159265358979323846f;
inline float deg_to_rad(float deg) { return deg * (kPi / 180.0f); }
inline float rad_to_deg(float rad) { return rad * (180.0f / kPi); }
inline float clampf(float v, float lo, float hi) { return v < lo ? lo : (v > hi ? hi : v); }
inline float safe_acos(float c) { return std::acos(clampf(c, -1.0f, 1.0f)); }

}  // namespace spinhash
