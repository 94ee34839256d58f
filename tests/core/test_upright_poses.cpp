// Poses that leave the model standing (max_tilt_deg, recognize/hypotheses.cpp):
// a doublet fixes no axis, so a vehicle's flat side can match a roof and
// pose a model on its side. An airborne, georeferenced query has z up, and
// a doublet's pose that tilts the model's up axis past max_tilt_deg is not
// verified (stats.poses_tilted counts it).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kModel = 3;
constexpr double kYaw = 0.9;        // rad: the query's true heading
constexpr float kAnyTilt = 180.0f;  // max_tilt_deg that lets every pose through
// The model's up axis under a pose: its z-component (rotation row-major, R[8]).
// A model on its side: |z| at most this (the axis lies near the horizontal).
constexpr float kOnItsSide = 0.3f;
// The bound is on the doublets' poses: refinement may turn a verified pose
// further towards what the points say (here from 45 to 51 degrees, the
// side's pull): the default's 45 degrees (cos 0.707) with 10 of slack.
constexpr float kUprightAfterRefinement = 0.57f;  // cos(55 degrees)

float up_z(const Pose& p) { return p.rotation[8]; }

struct Upright {
  const test::ToyDatabase& toy = test::shared_toy_database();
  host::AlignedBytes ws;  // the ranking lives here: kept until the next recognize

  Result recognize(const std::vector<double>& xyz, float max_tilt_deg) {
    RecognizerConfig cfg;
    cfg.draws.max_tilt_deg = max_tilt_deg;
    ws = host::AlignedBytes(required_workspace_bytes(cfg));
    Recognizer r;
    REQUIRE(r.init(&toy.db, cfg, ws.data(), ws.size()) == Status::kOk);
    Result res = r.recognize(xyz.data(), static_cast<uint32_t>(xyz.size() / 3));
    REQUIRE(res.status == Status::kOk);
    REQUIRE(res.ranking_count > 0);
    return res;
  }
  static std::vector<double> view() {
    const double t[3] = {40.0, 12.0, 1.0};
    return test::toy_query(test::toy_vehicle_points(kModel, 0.05f), kYaw, t, 0.03, 17);
  }
  // The same view turned a quarter about the x axis through its centroid: the vehicle lies on its side.
  static std::vector<double> on_its_side() {
    std::vector<double> xyz = view();
    double c[3] = {0.0, 0.0, 0.0};
    const double n = static_cast<double>(xyz.size() / 3);
    for (size_t i = 0; i < xyz.size(); ++i) c[i % 3] += xyz[i] / n;
    for (size_t i = 0; i < xyz.size(); i += 3) {
      const double y = xyz[i + 1] - c[1], z = xyz[i + 2] - c[2];
      xyz[i + 1] = c[1] - z;
      xyz[i + 2] = c[2] + y;
    }
    return xyz;
  }
};

}  // namespace

TEST_CASE_FIXTURE(Upright, "a vehicle on its side is posed on its side only when any tilt is allowed") {
  const Result any = recognize(on_its_side(), kAnyTilt);
  CHECK(any.ranking[0].model == kModel);
  CHECK(std::fabs(up_z(any.ranking[0].pose)) < kOnItsSide);
  CHECK(any.stats.draws.poses_tilted == 0u);

  const Result standing = recognize(on_its_side(), RecognizerConfig{}.draws.max_tilt_deg);
  CHECK(standing.stats.draws.poses_tilted > 0u);
  for (uint32_t k = 0; k < standing.ranking_count; ++k) {
    INFO("rank ", k, ", model ", standing.ranking[k].model);
    if (standing.ranking[k].has_pose) CHECK(up_z(standing.ranking[k].pose) >= kUprightAfterRefinement);
  }
  CHECK_FALSE(standing.confident);
}

TEST_CASE_FIXTURE(Upright, "a standing vehicle gets the same answer from fewer verified poses") {
  const Result any = recognize(view(), kAnyTilt);
  CHECK(any.ranking[0].model == kModel);
  // The ranking lives in the workspace, which the next recognize replaces.
  const Pose any_pose = any.ranking[0].pose;
  const uint32_t any_hypotheses = any.stats.draws.hypotheses;
  const Result standing = recognize(view(), RecognizerConfig{}.draws.max_tilt_deg);
  CHECK(standing.ranking[0].model == kModel);
  CHECK(standing.stats.draws.poses_tilted > 0u);  // flat patches pair with sides
  CHECK(standing.stats.draws.hypotheses < any_hypotheses);
  for (int a = 0; a < 3; ++a)
    CHECK(standing.ranking[0].pose.translation[a] == doctest::Approx(any_pose.translation[a]).epsilon(0.01));
  CHECK(up_z(standing.ranking[0].pose) == doctest::Approx(up_z(any_pose)).epsilon(0.01));
}
