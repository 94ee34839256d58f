// floor of a float as an int, for |t| < 2^23 (the grids' clamped cell
// coordinates): exact either way; and of a double as an int64.
#pragma once
#include <cmath>
#include <cstdint>

namespace spinhash {

inline int32_t floor_to_int(float t) {
#if defined(__SSE4_1__) || defined(__aarch64__) || !defined(__SSE2__)
  // floor is one instruction here (roundss, frintm), or nothing better is known.
  return static_cast<int32_t>(std::floor(t));
#else
  // SSE2 has no rounding instruction: floorf is a dozen. Truncate, and step
  // down where truncation rounded up (t negative, not whole); below 2^23 the
  // int converts back to float exactly.
  const int32_t i = static_cast<int32_t>(t);
  return static_cast<float>(i) > t ? i - 1 : i;
#endif
}

// floor of a double as an int64, for |v| < 2^62: exact (the truncation,
// one less where it rounded up), without a libm call on SSE2.
inline int64_t floor_to_int64(double v) {
  const auto t = static_cast<int64_t>(v);
  return static_cast<double>(t) > v ? t - 1 : t;
}

}  // namespace spinhash
