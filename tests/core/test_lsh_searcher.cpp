// The LSH candidate search (spinhash/internal/lsh_search.hpp): sorted, W-long
// results, the truncation flag exactly when the scan bound is reached, and the
// per-model exhaustive search against brute force.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "spinhash/arena.hpp"
#include "spinhash/internal/l1_distance.hpp"
#include "spinhash/internal/lsh_search.hpp"
#include "spinhash/lsh.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

struct Searcher {
  std::vector<unsigned char> memory;
  LshSearcher lsh;
  explicit Searcher(uint32_t max_scan) {
    Arena counter;
    LshSearcher sizing;
    sizing.carve(counter, max_scan);
    memory.resize(counter.used() + 64);
    Arena arena(memory.data(), memory.size());
    REQUIRE(lsh.carve(arena, max_scan));
  }
};

bool sorted(const Candidate* c, uint32_t n) {
  for (uint32_t i = 1; i < n; ++i)
    if (c[i - 1].distance > c[i].distance ||
        (c[i - 1].distance == c[i].distance && c[i - 1].feature >= c[i].feature))
      return false;
  return true;
}

bool before(const Candidate& a, const Candidate& b) {
  return a.distance < b.distance || (a.distance == b.distance && a.feature < b.feature);
}

// The distinct features of the probe's L buckets, sorted by (distance, feature).
std::vector<Candidate> bucket_union_sorted(const Database& db, const uint8_t* probe) {
  const blob::Params& p = db.params();
  std::vector<uint32_t> features;
  for (uint32_t t = 0; t < p.lsh_tables; ++t) {
    const uint32_t b = blob::bucket_of(lsh_key(db.lsh_bits(t), p.lsh_bits, probe), t, p.lsh_buckets);
    const uint32_t* entries = db.lsh_entries() + static_cast<size_t>(t) * p.feature_count;
    for (uint32_t e = db.lsh_offsets(t)[b]; e < db.lsh_offsets(t)[b + 1u]; ++e)
      features.push_back(entries[e]);
  }
  std::sort(features.begin(), features.end());
  features.erase(std::unique(features.begin(), features.end()), features.end());
  std::vector<Candidate> all;
  for (uint32_t f : features) all.push_back(Candidate{f, l1_distance(probe, db.spin(f), db.spin_dims())});
  std::sort(all.begin(), all.end(), before);
  return all;
}

}  // namespace

TEST_CASE("LSH search keeps exactly the W nearest distinct features of the query's buckets") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  Searcher s(1u << 20);
  Candidate out[128];
  uint32_t replaced = 0;  // probes whose buckets hold more than W: the list had to evict
  for (uint32_t w : {1u, 5u, 50u}) {
    for (uint32_t f = 1; f < toy.db.feature_count(); f += 61) {
      const std::vector<Candidate> all = bucket_union_sorted(toy.db, toy.db.spin(f));
      SearchStats st;
      const uint32_t n = s.lsh.search(toy.db, toy.db.spin(f), w, out, &st);
      REQUIRE(n == std::min<size_t>(w, all.size()));
      replaced += all.size() > w ? 1u : 0u;
      for (uint32_t i = 0; i < n; ++i) {
        CHECK(out[i].feature == all[i].feature);
        CHECK(out[i].distance == all[i].distance);
      }
    }
  }
  CHECK(replaced > 10u);
}

TEST_CASE("LSH search: a database feature finds itself first, W sorted candidates, no truncation") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  Searcher s(1u << 20);
  const uint32_t w = 20;
  Candidate out[128];
  for (uint32_t f = 0; f < toy.db.feature_count(); f += 97) {
    SearchStats st;
    const uint32_t n = s.lsh.search(toy.db, toy.db.spin(f), w, out, &st);
    REQUIRE(n >= 1u);
    CHECK(n <= w);
    CHECK(out[0].distance == 0u);
    CHECK(sorted(out, n));
    CHECK_FALSE(st.truncated);
    for (uint32_t i = 0; i < n; ++i)
      CHECK(out[i].distance == l1_distance(toy.db.spin(f), toy.db.spin(out[i].feature), toy.db.spin_dims()));
  }
}

TEST_CASE("LSH search: the scan bound truncates, and says so") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const uint32_t f = toy.db.feature_count() / 2;
  SearchStats full;
  Candidate out[128];
  Searcher wide(1u << 20);
  wide.lsh.search(toy.db, toy.db.spin(f), 50, out, &full);
  REQUIRE(full.entries_scanned > 8u);
  CHECK_FALSE(full.truncated);
  SearchStats cut;
  Searcher narrow(8);
  narrow.lsh.search(toy.db, toy.db.spin(f), 50, out, &cut);
  CHECK(cut.truncated);
  CHECK(cut.entries_scanned <= 8u);
  // set_scan lowers the bound of a wide searcher, and cannot raise it past its carve.
  SearchStats lowered;
  wide.lsh.set_scan(8);
  wide.lsh.search(toy.db, toy.db.spin(f), 50, out, &lowered);
  CHECK(lowered.truncated);
  CHECK(lowered.entries_scanned == cut.entries_scanned);
  SearchStats raised;
  narrow.lsh.set_scan(1u << 20);
  narrow.lsh.search(toy.db, toy.db.spin(f), 50, out, &raised);
  CHECK(raised.entries_scanned == cut.entries_scanned);
}

TEST_CASE("exhaustive per-model search equals a brute-force sort by (distance, feature)") {
  const test::ToyDatabase& toy = test::shared_toy_database();
  const uint32_t dims = toy.db.spin_dims();
  // Many probes and list sizes: the scan stops a distance early once the
  // list is full, which must never change the list.
  const uint32_t kProbeStride = 7;
  for (uint32_t probe_feature = 0; probe_feature < toy.db.feature_count(); probe_feature += kProbeStride) {
    const uint8_t* probe = toy.db.spin(probe_feature);
    for (uint32_t w : {1u, 5u, 8u}) {
      for (uint32_t m = 0; m < toy.db.model_count(); ++m) {
        const blob::ModelRecord& rec = toy.db.model(m);
        std::vector<Candidate> all;
        for (uint32_t f = rec.first_feature; f < rec.first_feature + rec.feature_count; ++f)
          all.push_back(Candidate{f, l1_distance(probe, toy.db.spin(f), dims)});
        std::sort(all.begin(), all.end(), [](const Candidate& a, const Candidate& b) {
          return a.distance < b.distance || (a.distance == b.distance && a.feature < b.feature);
        });
        Candidate out[8];
        const uint32_t n = search_model_exhaustive(toy.db, m, probe, w, out);
        REQUIRE(n == std::min<uint32_t>(w, rec.feature_count));
        for (uint32_t i = 0; i < n; ++i) {
          REQUIRE(out[i].feature == all[i].feature);
          REQUIRE(out[i].distance == all[i].distance);
        }
      }
    }
  }
}
