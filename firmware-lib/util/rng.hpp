// Seeded generator of the core (PCG32, O'Neill 2014): the same sequence on
// every target and standard library, unlike rand() or <random> distributions.
#pragma once
#include <cstdint>

namespace spinhash {

class Pcg32 {
 public:
  explicit Pcg32(uint64_t seed, uint64_t stream = 0x5851F42D4C957F2Dull)
      : state_(0), inc_((stream << 1u) | 1u) {
    next();
    state_ += seed;
    next();
  }
  uint32_t next() {
    uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  // Uniform in [0, 1) with 24 bits, exact in float.
  float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
  // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; bias < n / 2^32).
  uint32_t below(uint32_t n) { return static_cast<uint32_t>((static_cast<uint64_t>(next()) * n) >> 32); }

 private:
  uint64_t state_;
  uint64_t inc_;
};

}  // namespace spinhash
