// LSH tables over quantised spin images (eq. 2): bit sampling with dims
// drawn in proportion to their range and thresholds uniform within it.
#pragma once
#include <cstdint>
#include <vector>

#include "spinhash/blob_format.hpp"

namespace spinhash {
namespace host {

struct LshTables {
  std::vector<blob::LshBit> bits;  // tables * bits_per_key
  std::vector<uint32_t> offsets;   // tables * (buckets + 1)
  std::vector<uint32_t> entries;   // tables * features
  uint32_t buckets = 0;
  float d_c = 0.0f;  // sum of per-dimension ranges
  uint32_t max_bucket = 0;
  double mean_bucket = 0.0;
};

// Per-dimension LSH range C_i: the `quantile` of the dimension's values
// over all features (at least 1); their sum is eq. 2's d_c.
std::vector<uint32_t> dimension_ranges(const std::vector<uint8_t>& spins, uint32_t dims, uint32_t features,
                                       float quantile);

LshTables build_lsh_tables(const std::vector<uint8_t>& spins, uint32_t dims, uint32_t features,
                           uint32_t tables, uint32_t bits_per_key, float range_quantile, uint64_t seed);

}  // namespace host
}  // namespace spinhash
