// Seeded random numbers that are identical on every standard library:
// std::mt19937_64 is fully specified by the standard, but the <random>
// distributions are not, so values are derived from raw bits here.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace spinhash::host {

// SplitMix64 finaliser: decorrelates seeds derived from (seed, stream).
inline uint64_t mix_seed(uint64_t seed, uint64_t stream) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class SeededRandom {
 public:
  explicit SeededRandom(uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1) from the top 53 bits.
  double uniform01() {
    constexpr double kTwoPowMinus53 = 1.0 / 9007199254740992.0;
    return static_cast<double>(engine_() >> 11) * kTwoPowMinus53;
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  // Uniform integer in [0, n) by the multiply-shift method (bias < 2^-32).
  uint32_t below(uint32_t n) {
    return static_cast<uint32_t>(((engine_() >> 32) * static_cast<uint64_t>(n)) >> 32);
  }
  bool chance(double probability) { return uniform01() < probability; }
  // Standard normal by Box-Muller (one value per call, deterministic).
  double gaussian() {
    constexpr double kTwoPi = 6.283185307179586;
    const double u1 = 1.0 - uniform01();  // in (0, 1]: log is finite
    const double u2 = uniform01();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace spinhash::host
