// L1 locality-sensitive hashing by bit sampling (section 5, eq. 2). A bit is
// "quantised bin `dim` exceeds `threshold`"; with dims drawn in proportion to
// their range C_i and thresholds uniform in [0, C_i), two images differ in a
// bit with probability L1 / d_c, d_c = sum C_i, so a K-bit key collides with
// probability (1 - d/d_c)^K and at least one of L tables with eq. 2.
#pragma once
#include <cstdint>

#include "spinhash/blob_format.hpp"

namespace spinhash {

inline uint64_t lsh_key(const blob::LshBit* bits, uint32_t k, const uint8_t* spin) {
  uint64_t key = 0;
  for (uint32_t i = 0; i < k; ++i)
    key |= static_cast<uint64_t>(spin[bits[i].dim] > bits[i].threshold ? 1u : 0u) << i;
  return key;
}

}  // namespace spinhash
