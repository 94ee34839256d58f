// Counters that stop at their type's top instead of wrapping: a scene's
// 32-bit statistics summed over windows and bands.
#pragma once
#include <cstdint>

namespace spinhash {

inline uint32_t saturating_add(uint32_t a, uint64_t b) {
  const uint64_t s = static_cast<uint64_t>(a) + b;
  return s > 0xFFFFFFFFull ? 0xFFFFFFFFu : static_cast<uint32_t>(s);
}

}  // namespace spinhash
