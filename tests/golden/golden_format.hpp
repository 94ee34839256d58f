// Layout of the golden vectors (tests/golden/): what record_golden.cpp writes
// and test_golden.cpp checks on every target. See tests/golden/README.md.
#pragma once
#include <cstdint>

#include "spinhash/config.hpp"

namespace spinhash {
namespace golden {

constexpr uint32_t kMaxGoldenRanked = 8;     // ranking entries kept per query
constexpr uint32_t kBytesPerCoordinate = 2;  // golden_queries.i16: little-endian int16 millimetres
constexpr float kMetresPerUnit = 0.001f;

// One coordinate of golden_queries.i16: a single float multiply, so the
// same float on every IEEE target.
inline float decode_mm(const uint8_t* le) {
  const auto u = static_cast<uint16_t>(le[0] | (le[1] << 8));
  return static_cast<float>(static_cast<int16_t>(u)) * kMetresPerUnit;
}

struct GoldenEntry {
  uint32_t model;
  float score;
};

struct GoldenQuery {
  uint32_t first_point;  // index of its first xyz triple in golden_queries.i16
  uint32_t point_count;
  Mode mode;
  uint32_t features;    // stats.extract.features
  uint32_t hypotheses;  // stats.draws.hypotheses
  bool budget_exhausted;
  uint32_t ranking_count;
  GoldenEntry ranking[kMaxGoldenRanked];  // the first min(ranking_count, kMaxGoldenRanked)
  double pose[12];                        // best model: rotation row-major, then translation
};

}  // namespace golden
}  // namespace spinhash

namespace spinhash {
namespace golden {

// The one recognizer setting used to record and to check: defaults, with the
// capacities of a small onboard workspace and a third of the default
// hypothesis budget (the check is about identical answers, and powerpc under
// QEMU runs these queries some 40x slower than the host).
constexpr uint32_t kGoldenMaxHypotheses = 2000;

inline RecognizerConfig golden_config(Mode mode) {
  RecognizerConfig c;
  c.mode = mode;
  c.seed = 7;
  c.max_points = 8192;
  c.max_models = 16;
  c.draws.max_hypotheses = kGoldenMaxHypotheses;
  return c;
}

}  // namespace golden
}  // namespace spinhash
