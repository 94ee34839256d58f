// The portable scalar reference of the L1 kernels: the definition every
// optimised kernel must reproduce bit for bit (tests/core/test_kernels.cpp),
// and the kernel of targets without one (bare-metal Cortex-M, armhf without
// NEON, SPINHASH_KERNELS_REFERENCE).
#pragma once
#include <cstdint>

#include "kernels/l1_blocks.hpp"

namespace spinhash {
namespace kernels {
namespace reference {

constexpr const char* kName = "reference";

inline uint32_t sad(const uint8_t* a, const uint8_t* b, uint32_t n) {
  uint32_t sum = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const int32_t d = static_cast<int32_t>(a[i]) - static_cast<int32_t>(b[i]);
    sum += static_cast<uint32_t>(d < 0 ? -d : d);
  }
  return sum;
}

inline uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) { return sad(a, b, dims); }

inline uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  return within_by_blocks<sad>(a, b, dims, bound);
}

}  // namespace reference
}  // namespace kernels
}  // namespace spinhash
