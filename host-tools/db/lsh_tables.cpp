#include "db/lsh_tables.hpp"

#include <algorithm>
#include <random>

#include "spinhash/lsh.hpp"

namespace spinhash {
namespace host {
namespace {

// Draws a value in [0, n) from 64 random bits (same on every standard library).
uint32_t draw_below(std::mt19937_64& rng, uint64_t n) { return static_cast<uint32_t>(rng() % n); }

std::vector<blob::LshBit> sample_bits(const std::vector<uint32_t>& range, uint32_t count, uint64_t seed) {
  std::vector<uint64_t> cumulative(range.size());
  uint64_t total = 0;
  for (size_t d = 0; d < range.size(); ++d) cumulative[d] = (total += range[d]);
  std::mt19937_64 rng(seed);
  std::vector<blob::LshBit> bits(count);
  for (auto& bit : bits) {
    // A point uniform on [0, d_c): its dimension is drawn with probability
    // C_i / d_c and its offset inside that dimension is the threshold.
    uint64_t u = draw_below(rng, total);
    size_t d = 0;
    while (cumulative[d] <= u) ++d;
    bit.dim = static_cast<uint16_t>(d);
    bit.threshold = static_cast<uint16_t>(u - (cumulative[d] - range[d]));
  }
  return bits;
}

// Buckets per table: the power of two that leaves 8 to 16 features per
// bucket on average. Distinct keys sharing a bucket only add entries to
// re-rank by exact L1 (within the scan bound); the offsets then cost
// 4 L B / N = 2 to 4 bytes per feature (L = 8), which keeps the blob under
// 160 B per feature (176 B with two features per bucket).
constexpr uint32_t kFeaturesPerBucket = 16;

uint32_t bucket_count_for(uint32_t features) {
  uint32_t b = 1;
  while (b < features / kFeaturesPerBucket && b < (1u << 28)) b <<= 1u;
  return b;
}

}  // namespace

// Per-dimension range C_i, the `quantile` of the dimension's values (at least 1):
// thresholds 0..C_i-1 make P(bit differs) = |min(q1, C_i) - min(q2, C_i)| / C_i,
// so eq. 2 holds exactly for the clamped images. Clamping at a high quantile
// instead of the maximum keeps d_c near the distances that matter: spin images
// are sparse and heavy-tailed, and d_c = sum of maxima makes every key collide.
std::vector<uint32_t> dimension_ranges(const std::vector<uint8_t>& spins, uint32_t dims, uint32_t features,
                                       float quantile) {
  std::vector<uint32_t> range(dims, 1u);
  std::vector<uint32_t> histogram(256);
  const uint64_t rank = static_cast<uint64_t>(quantile * static_cast<float>(features));
  for (uint32_t d = 0; d < dims; ++d) {
    std::fill(histogram.begin(), histogram.end(), 0u);
    for (uint32_t f = 0; f < features; ++f) ++histogram[spins[static_cast<size_t>(f) * dims + d]];
    uint64_t seen = 0;
    uint32_t v = 0;
    while (v < 255u && (seen += histogram[v]) <= rank) ++v;
    range[d] = std::max(1u, v);
  }
  return range;
}

LshTables build_lsh_tables(const std::vector<uint8_t>& spins, uint32_t dims, uint32_t features,
                           uint32_t tables, uint32_t bits_per_key, float range_quantile, uint64_t seed) {
  LshTables t;
  std::vector<uint32_t> range = dimension_ranges(spins, dims, features, range_quantile);
  for (uint32_t r : range) t.d_c += static_cast<float>(r);
  t.bits = sample_bits(range, tables * bits_per_key, seed);
  t.buckets = bucket_count_for(features);
  t.offsets.assign(static_cast<size_t>(tables) * (t.buckets + 1u), 0u);
  t.entries.resize(static_cast<size_t>(tables) * features);
  std::vector<uint32_t> bucket(features);
  uint64_t nonempty = 0;
  for (uint32_t tab = 0; tab < tables; ++tab) {
    uint32_t* off = t.offsets.data() + static_cast<size_t>(tab) * (t.buckets + 1u);
    const blob::LshBit* bits = t.bits.data() + static_cast<size_t>(tab) * bits_per_key;
    for (uint32_t f = 0; f < features; ++f) {
      uint64_t key = lsh_key(bits, bits_per_key, spins.data() + static_cast<size_t>(f) * dims);
      bucket[f] = blob::bucket_of(key, tab, t.buckets);
      ++off[bucket[f] + 1u];
    }
    for (uint32_t b = 0; b < t.buckets; ++b) {
      if (off[b + 1u] > t.max_bucket) t.max_bucket = off[b + 1u];
      nonempty += off[b + 1u] > 0 ? 1u : 0u;
      off[b + 1u] += off[b];
    }
    std::vector<uint32_t> cursor(off, off + t.buckets);
    uint32_t* entries = t.entries.data() + static_cast<size_t>(tab) * features;
    for (uint32_t f = 0; f < features; ++f) entries[cursor[bucket[f]]++] = f;  // ascending ids per bucket
  }
  t.mean_bucket = nonempty > 0 ? static_cast<double>(tables) * features / static_cast<double>(nonempty) : 0.0;
  return t;
}

}  // namespace host
}  // namespace spinhash
