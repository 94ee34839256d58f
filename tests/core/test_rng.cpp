// The core's PCG32 stream (util/rng.hpp): the reference outputs of O'Neill's
// pcg32 (pcg32_srandom_r(&rng, 42, 54), pcg32-demo), identical on every target.
#include <doctest/doctest.h>

#include <cstdint>

#include "util/rng.hpp"

using namespace spinhash;

TEST_CASE("PCG32 reproduces the reference sequence of seed 42, stream 54") {
  Pcg32 rng(42u, 54u);
  const uint32_t reference[6] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
  for (uint32_t expected : reference) CHECK(rng.next() == expected);
}

TEST_CASE("PCG32 uniform and below stay in range and follow the stream") {
  Pcg32 a(7u), b(7u);
  for (int i = 0; i < 1000; ++i) {
    const uint32_t raw = b.next();
    const float u = a.uniform();
    CHECK(u >= 0.0f);
    CHECK(u < 1.0f);
    CHECK(u == static_cast<float>(raw >> 8) * (1.0f / 16777216.0f));
  }
  Pcg32 c(9u), d(9u);
  for (int i = 0; i < 1000; ++i) {
    const uint32_t n = 1u + static_cast<uint32_t>(i);
    const uint32_t x = c.below(n);
    CHECK(x < n);
    CHECK(x == static_cast<uint32_t>((static_cast<uint64_t>(d.next()) * n) >> 32));
  }
}
