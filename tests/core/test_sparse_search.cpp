// More draws and a wider LSH scan for a sparse scan (recognize/sparse_search.hpp):
// the density of the query's footprint before any pose, and the scales it sets.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "recognize/sparse_search.hpp"
#include "support/geometry_fixtures.hpp"

using namespace spinhash;

namespace {

const RecognizerConfig kDefaults;
const float kSparseBelow = kDefaults.candidates.sparse_density;            // object points per m^2
const uint32_t kSparseTrialScale = kDefaults.draws.sparse_trial_scale;     // 4
const uint32_t kSparseScanScale = kDefaults.candidates.sparse_scan_scale;  // 4

// The candidates' parameters with max_bucket_scan `scan`.
StageParams with_scan(uint32_t scan) {
  StageParams p;
  p.candidates.max_bucket_scan = scan;
  return p;
}

// The top and sides of a 4.6 x 1.9 x 1.4 m car, yawed, as query features.
std::vector<float> yawed_car(float yaw) {
  const std::vector<float> box = test::box_surface(4.6f, 1.9f, 1.4f, 0.2f);
  std::vector<float> out;
  const float c = std::cos(yaw), s = std::sin(yaw);
  for (size_t i = 0; i < box.size(); i += 3) {
    out.push_back(c * box[i] - s * box[i + 1] + 12.0f);
    out.push_back(s * box[i] + c * box[i + 1] - 7.0f);
    out.push_back(box[i + 2]);
  }
  return out;
}

}  // namespace

TEST_CASE("footprint density: points per m^2 of the features' extent along their principal axes, any yaw") {
  for (const float yaw : {0.0f, 0.5f, 1.2f, 2.9f}) {
    CAPTURE(yaw);
    const std::vector<float> xyz = yawed_car(yaw);
    QueryFeatures q;
    q.positions = xyz.data();
    q.count = static_cast<uint32_t>(xyz.size() / 3);
    // 4.6 x 1.9 = 8.74 m^2 whatever the yaw (an axis-aligned box would grow to 4.6 x 4.6 at 45 degrees).
    CHECK(footprint_density(q, 874u) == doctest::Approx(100.0f).epsilon(0.02));
    // A survey at 10-30 points per m^2 returns 100-250 points of such a car: four times the draws.
    CHECK(trial_scale(kDefaults, footprint_density(q, 200u)) == kSparseTrialScale);
    // The scans that may name a model keep the configured budget.
    CHECK(trial_scale(kDefaults, footprint_density(q, 874u)) == 1u);
  }
  CHECK(kSparseTrialScale == 4u);
  CHECK(trial_scale(kDefaults, kSparseBelow) == 1u);
  CHECK(trial_scale(kDefaults, kSparseBelow - 0.5f) == kSparseTrialScale);
  QueryFeatures none;
  CHECK(footprint_density(none, 100u) == 0.0f);
}

TEST_CASE("a sparse scan's lookups scan four times the entries, within the dense query's total") {
  constexpr uint32_t kScan = 1024, kFeatures = 1024;
  const StageParams p = with_scan(kScan);
  const float sparse = kSparseBelow - 0.5f;
  // Dense scans keep the configured bound, whatever their feature count.
  CHECK(bucket_scan(p, kFeatures, kSparseBelow, 200u) == kScan);
  // A sparse car's 100-300 features: four times it, the seen set's bound.
  CHECK(kSparseScanScale == 4u);
  CHECK(sparse_bucket_scan(p.candidates) == kSparseScanScale * kScan);
  CHECK(bucket_scan(p, kFeatures, sparse, 200u) == kSparseScanScale * kScan);
  // Many features share max_features x max_bucket_scan, never below the configured bound.
  CHECK(bucket_scan(p, kFeatures, sparse, 512u) == kFeatures * kScan / 512u);
  CHECK(bucket_scan(p, kFeatures, sparse, kFeatures) == kScan);
  CHECK(bucket_scan(p, kFeatures, sparse, 0u) == kScan);
  // Up to max_sparse_bucket_scan: a small bound is scaled, a large one kept.
  const uint32_t most = kDefaults.candidates.max_sparse_bucket_scan;
  CHECK(sparse_bucket_scan(with_scan(256u).candidates) == 1024u);
  CHECK(sparse_bucket_scan(with_scan(2048u).candidates) == most);
  CHECK(sparse_bucket_scan(with_scan(1u << 24).candidates) == 1u << 24);
  for (uint32_t scan : {1u, 100u, 512u, 1024u, 3000u, 4096u, 70000u})
    for (uint32_t n : {1u, 50u, 300u, 700u, 1024u}) {
      CAPTURE(scan);
      CAPTURE(n);
      const uint32_t b = bucket_scan(with_scan(scan), kFeatures, sparse, n);
      CHECK(b >= scan);
      CHECK(b <= sparse_bucket_scan(with_scan(scan).candidates));
    }
}
