// More draws for a sparse scan (recognize/sparse_search.hpp): the density of
// the query's footprint before any pose, and the draws' scale it sets.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "recognize/confidence.hpp"
#include "recognize/sparse_search.hpp"
#include "support/geometry_fixtures.hpp"

using namespace spinhash;

namespace {

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
    CHECK(trial_scale(footprint_density(q, 200u)) == kSparseTrialScale);
    // The scans that may name a model keep the configured budget.
    CHECK(trial_scale(footprint_density(q, 874u)) == 1u);
  }
  CHECK(trial_scale(kMinModelDensity) == 1u);
  CHECK(trial_scale(kMinModelDensity - 0.5f) == kSparseTrialScale);
  QueryFeatures none;
  CHECK(footprint_density(none, 100u) == 0.0f);
}
