// LSH collision rates against eq. 2 with the tables the database builder makes.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "db/lsh_tables.hpp"
#include "spinhash/internal/l1_distance.hpp"
#include "spinhash/internal/lsh_probability.hpp"
#include "spinhash/internal/lsh_search.hpp"
#include "spinhash/lsh.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kDims = 100;
constexpr uint32_t kMaxValue = 40;  // every dimension's range C_i is then 40: no clamping

struct Lcg {  // deterministic and standard-library independent
  uint64_t s;
  uint32_t below(uint32_t n) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<uint32_t>((s >> 33) % n);
  }
};

std::vector<uint8_t> random_images(uint32_t count, Lcg& rng) {
  std::vector<uint8_t> v(static_cast<size_t>(count) * kDims);
  for (auto& x : v) x = static_cast<uint8_t>(rng.below(kMaxValue + 1));
  return v;
}

// b = a moved by exactly `distance` in L1: each step pushes one dimension
// further from a's value (never back), staying inside [0, kMaxValue].
std::vector<uint8_t> at_distance(const uint8_t* a, uint32_t distance, Lcg& rng) {
  std::vector<uint8_t> b(a, a + kDims);
  uint32_t moved = 0;
  for (uint32_t guard = 0; moved < distance && guard < 1000000u; ++guard) {
    uint32_t d = rng.below(kDims);
    bool up = b[d] > a[d] || (b[d] == a[d] && rng.below(2) == 0);
    if (up && b[d] < kMaxValue) {
      ++b[d];
      ++moved;
    } else if (!up && b[d] > 0) {
      --b[d];
      ++moved;
    }
  }
  uint32_t l1 = 0;
  for (uint32_t i = 0; i < kDims; ++i) l1 += static_cast<uint32_t>(std::abs(int(a[i]) - int(b[i])));
  REQUIRE(l1 == distance);
  return b;
}

}  // namespace

TEST_CASE("bit-sampling LSH collides as eq. 2 predicts") {
  Lcg rng{42};
  const uint32_t features = 1000, tables = 64, bits = 8, groups_of = 8;
  std::vector<uint8_t> db = random_images(features, rng);
  host::LshTables t = host::build_lsh_tables(db, kDims, features, tables, bits, 0.999f, 7);
  REQUIRE(t.d_c == doctest::Approx(kDims * kMaxValue));
  for (uint32_t distance : {40u, 200u, 600u}) {
    uint32_t same_table = 0, same_group = 0, pairs = 300;
    for (uint32_t p = 0; p < pairs; ++p) {
      const uint8_t* a = db.data() + static_cast<size_t>(p) * kDims;
      std::vector<uint8_t> b = at_distance(a, distance, rng);
      for (uint32_t g = 0; g < tables / groups_of; ++g) {
        bool any = false;
        for (uint32_t k = 0; k < groups_of; ++k) {
          const blob::LshBit* tb = t.bits.data() + (g * groups_of + k) * bits;
          bool hit = lsh_key(tb, bits, a) == lsh_key(tb, bits, b.data());
          same_table += hit ? 1u : 0u;
          any = any || hit;
        }
        same_group += any ? 1u : 0u;
      }
    }
    const double per_table = static_cast<double>(same_table) / (pairs * tables);
    const double per_group = static_cast<double>(same_group) / (pairs * (tables / groups_of));
    CAPTURE(distance);
    CHECK(per_table ==
          doctest::Approx(std::pow(1.0 - distance / static_cast<double>(t.d_c), bits)).epsilon(0.08));
    CHECK(per_group ==
          doctest::Approx(lsh_collision_probability(distance, t.d_c, bits, groups_of)).epsilon(0.08));
  }
}

TEST_CASE("eq. 2 at its limits") {
  CHECK(lsh_collision_probability(0.0, 100.0, 10, 5) == doctest::Approx(1.0));
  CHECK(lsh_collision_probability(100.0, 100.0, 10, 5) == doctest::Approx(0.0));
  CHECK(lsh_collision_probability(10.0, 100.0, 1, 1) == doctest::Approx(0.9));
  // more bits: fewer collisions; more tables: more
  CHECK(lsh_collision_probability(20.0, 100.0, 10, 5) < lsh_collision_probability(20.0, 100.0, 5, 5));
  CHECK(lsh_collision_probability(20.0, 100.0, 10, 10) > lsh_collision_probability(20.0, 100.0, 10, 5));
}

TEST_CASE("the W best candidates stay sorted by distance, then feature id") {
  Candidate list[4];
  uint32_t n = 0;
  for (Candidate c : {Candidate{9, 50}, Candidate{3, 10}, Candidate{7, 50}, Candidate{1, 90}, Candidate{2, 5},
                      Candidate{8, 10}})
    insert_top_w(list, &n, 4, c);
  REQUIRE(n == 4);
  CHECK(list[0].feature == 2);
  CHECK(list[1].feature == 3);
  CHECK(list[2].feature == 8);
  CHECK(list[3].feature == 7);  // 7 before 9 at equal distance; 1 (90) dropped
}

TEST_CASE("the bounded L1 distance is exact up to its bound and above it beyond, at any length") {
  Lcg rng{11};
  for (uint32_t dims : {1u, 17u, 64u, 100u, 129u, 225u}) {
    std::vector<uint8_t> a(dims), b(dims);
    for (uint32_t trial = 0; trial < 50; ++trial) {
      for (uint32_t i = 0; i < dims; ++i)
        a[i] = static_cast<uint8_t>(rng.below(256)), b[i] = static_cast<uint8_t>(rng.below(256));
      uint32_t exact = 0;
      for (uint32_t i = 0; i < dims; ++i) exact += static_cast<uint32_t>(std::abs(int(a[i]) - int(b[i])));
      CAPTURE(dims);
      REQUIRE(l1_distance(a.data(), b.data(), dims) == exact);
      for (uint32_t bound : {0u, exact / 3u, exact - (exact > 0 ? 1u : 0u), exact, exact + 1u, 0xFFFFFFFFu}) {
        const uint32_t d = l1_distance_within(a.data(), b.data(), dims, bound);
        if (exact <= bound)
          CHECK(d == exact);
        else
          CHECK(d > bound);  // stopped early or not: never at or below the bound
        CHECK(d <= exact);   // a partial sum at most
      }
    }
  }
  // A partial sum that reaches the bound exactly at a block's end is no
  // reason to stop: a candidate at the bound may still enter (ties go by
  // feature index).
  const std::vector<uint8_t> zeros(kDims, 0), ones(kDims, 1);
  CHECK(l1_distance_within(zeros.data(), ones.data(), kDims, 64u) == kDims);
}
