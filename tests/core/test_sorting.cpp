// top_n and heap_sort (util/) against std::sort on seeded random data with ties.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "util/heap_sort.hpp"
#include "util/rng.hpp"
#include "util/top_n.hpp"

using namespace spinhash;

namespace {

// Values with many ties (0..19), ordered by value descending, then index.
std::vector<uint32_t> tied_values(uint32_t n, uint64_t seed) {
  Pcg32 rng(seed);
  std::vector<uint32_t> v(n);
  for (uint32_t& x : v) x = rng.below(20);
  return v;
}

}  // namespace

TEST_CASE("top_n equals the first n of a std::sort, with ties broken by index") {
  for (uint64_t seed = 1; seed <= 20; ++seed)
    for (uint32_t n : {1u, 5u, 17u, 200u}) {
      const std::vector<uint32_t> v = tied_values(150, seed);
      auto better = [&](uint32_t a, uint32_t b) { return v[a] > v[b] || (v[a] == v[b] && a < b); };
      auto keep = [&](uint32_t i) { return v[i] % 3u != 0u; };  // a filter too
      std::vector<uint32_t> expected;
      for (uint32_t i = 0; i < v.size(); ++i)
        if (keep(i)) expected.push_back(i);
      std::sort(expected.begin(), expected.end(), better);
      if (expected.size() > n) expected.resize(n);
      std::vector<uint32_t> out(n);
      const uint32_t got = top_n(static_cast<uint32_t>(v.size()), n, out.data(), keep, better);
      REQUIRE(got == expected.size());
      for (uint32_t k = 0; k < got; ++k) CHECK(out[k] == expected[k]);
    }
}

TEST_CASE("heap_sort equals std::sort for a strict order, at every length") {
  for (uint32_t n = 0; n <= 70; ++n) {
    std::vector<uint32_t> v = tied_values(n, 100 + n);
    std::vector<uint64_t> keys(n), expected(n);
    for (uint32_t i = 0; i < n; ++i)
      keys[i] = expected[i] = (static_cast<uint64_t>(v[i]) << 32) | i;  // unique
    std::sort(expected.begin(), expected.end());
    heap_sort(keys.data(), n, [](uint64_t a, uint64_t b) { return a < b; });
    CHECK(keys == expected);
  }
}
