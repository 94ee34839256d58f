// The class envelope (recognize/class_envelope.hpp): the range of a class's
// members read from the database, the scan's shape as the air measures it,
// and the gate on the class flag. Geometry of real vehicles: a 1.25 m tall
// touring saloon (TORCS' 155-DTM, 4.8 x 1.9 m) against the procedural
// fleet's vans (1.65-2.10 m tall).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "recognize/class_envelope.hpp"
#include "spinhash/recognizer.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

Eigen::Matrix3f yaw_matrix(float yaw) {
  Eigen::Matrix3f r;
  r << std::cos(yaw), -std::sin(yaw), 0.0f, std::sin(yaw), std::cos(yaw), 0.0f, 0.0f, 0.0f, 1.0f;
  return r;
}

Eigen::Matrix3f pitch_matrix(float a) {  // about the model's y (its width)
  Eigen::Matrix3f r;
  r << std::cos(a), 0.0f, std::sin(a), 0.0f, 1.0f, 0.0f, -std::sin(a), 0.0f, std::cos(a);
  return r;
}

RigidPose yawed(float yaw) {
  RigidPose p;
  p.rotation = yaw_matrix(yaw);
  p.translation = Eigen::Vector3f(3.0f, -2.0f, 0.0f);
  return p;
}

// The surface of an l x w x h box standing on z = `base`, seen from the air:
// its top and sides down to `lowest` above the base (a sparse scan's lowest
// row), yawed and moved like a query.
std::vector<float> seen_box(float l, float w, float h, float base, float lowest, float spacing,
                            const RigidPose& pose) {
  const std::vector<float> box = test::box_surface(l, w, h, spacing);
  std::vector<float> out;
  for (size_t i = 0; i < box.size(); i += 3) {
    const float z = box[i + 2] + 0.5f * h;  // 0 .. h
    if (z < lowest) continue;
    const Eigen::Vector3f p =
        pose.rotation * Eigen::Vector3f(box[i], box[i + 1], base + z) + pose.translation;
    out.insert(out.end(), p.data(), p.data() + 3);
  }
  return out;
}

QueryFeatures features_of(const std::vector<float>& xyz) {
  QueryFeatures q;
  q.positions = xyz.data();
  q.count = static_cast<uint32_t>(xyz.size() / 3);
  return q;
}

// The fleet's van family as a database would hold it (8 members: their
// boxes, as `spinhash build` measures them from the model clouds).
ClassEnvelope fleet_vans() {
  ClassEnvelope e;
  e.members = 8;
  e.length_max = 5.45f;
  e.width_max = 2.08f;
  e.height_min = 1.62f;
  e.height_max = 2.25f;
  return e;
}

constexpr float kEndTolerance = 0.3f;  // max_extent_overhang
constexpr float kSigmaSurface = 0.1f;  // RefineParams::sigma_surface
const ClassesParams kClasses;          // the class stage's tolerances

}  // namespace

TEST_CASE("a class's envelope spans its members' boxes and nothing else") {
  // toy-0 (4.5 x 1.8, 0.3-1.75 m) and toy-5 (3.8 x 1.7, 0.3-1.55 m) are the sedans.
  const ClassEnvelope sedans =
      class_envelope(test::shared_toy_database().db, static_cast<uint32_t>(VehicleClass::kSedan));
  CHECK(sedans.members == 2u);
  CHECK(sedans.length_max == doctest::Approx(4.5f).epsilon(0.01));
  CHECK(sedans.width_max == doctest::Approx(1.8f).epsilon(0.01));
  CHECK(sedans.height_min == doctest::Approx(1.25f).epsilon(0.01));
  CHECK(sedans.height_max == doctest::Approx(1.45f).epsilon(0.01));
  const ClassEnvelope vans =
      class_envelope(test::shared_toy_database().db, static_cast<uint32_t>(VehicleClass::kVan));
  CHECK(vans.members == 1u);
  CHECK(vans.height_min == vans.height_max);
  CHECK(class_envelope(test::shared_toy_database().db, static_cast<uint32_t>(VehicleClass::kBus)).members ==
        0u);
  // A class without members holds no scan.
  CHECK_FALSE(within_envelope(ScanShape{}, ClassEnvelope{}, kEndTolerance, kClasses));
}

// A model record of a box, x along its length, its bottom at z = bottom.
blob::ModelRecord box_record(float l, float w, float bottom, float top) {
  blob::ModelRecord r{};
  r.bbox_min[0] = -0.5f * l, r.bbox_max[0] = 0.5f * l;
  r.bbox_min[1] = -0.5f * w, r.bbox_max[1] = 0.5f * w;
  r.bbox_min[2] = bottom, r.bbox_max[2] = top;
  return r;
}

TEST_CASE(
    "the scan's shape: spans along the pose's axes and the top above the terrain or the leader's bottom") {
  const RigidPose pose = yawed(0.7f);
  const blob::ModelRecord saloon = box_record(4.8f, 1.9f, 0.0f, 1.25f);
  const std::vector<float> xyz = seen_box(4.8f, 1.9f, 1.25f, 0.0f, 0.2f, 0.1f, pose);
  const QueryFeatures q = features_of(xyz);
  const ScanShape bare = measure_scan(q, saloon, pose, -1.0f, 0.0f, kSigmaSurface, 100.0f);
  CHECK(bare.length == doctest::Approx(4.8f).epsilon(0.03));
  CHECK(bare.width == doctest::Approx(1.9f).epsilon(0.06));
  CHECK_FALSE(bare.on_terrain);
  CHECK(bare.height == doctest::Approx(1.25f).epsilon(0.01));      // the top above the box bottom
  CHECK(bare.bottom_gap == doctest::Approx(0.21f).epsilon(0.05));  // the lowest row seen
  CHECK(bare.noise == kSigmaSurface);
  CHECK(bare.spacing == doctest::Approx(0.1f));  // 1 / sqrt(100 points per m^2)
  // Turned a quarter about z, the spans swap axes; length stays the longer.
  const RigidPose turned{pose.rotation * yaw_matrix(1.5707963f), pose.translation};
  CHECK(measure_scan(q, saloon, turned, -1.0f, 0.0f, kSigmaSurface, 100.0f).length ==
        doctest::Approx(bare.length).epsilon(0.01));
  const ScanShape ground = measure_scan(q, saloon, pose, 1.27f, 0.04f, kSigmaSurface, 100.0f);
  CHECK(ground.on_terrain);
  CHECK(ground.height == 1.27f);
  CHECK(ground.noise == 0.04f);
}

TEST_CASE("a 1.25 m saloon is no van: on terrain, and without terrain under a van's pose at either height") {
  const RigidPose pose = yawed(-0.4f);
  const ClassEnvelope vans = fleet_vans();
  const std::vector<float> dense = seen_box(4.8f, 1.9f, 1.25f, 0.0f, 0.15f, 0.1f, pose);
  // On terrain, 5 cm noise: the top above the terrain is the measure.
  const blob::ModelRecord van_on_ground = box_record(4.9f, 1.95f, 0.0f, 1.75f);
  const ScanShape on_ground =
      measure_scan(features_of(dense), van_on_ground, pose, 1.27f, 0.05f, kSigmaSurface, 150.0f);
  CHECK_FALSE(within_envelope(on_ground, vans, kEndTolerance, kClasses));
  ScanShape van = on_ground;  // a fleet van of 1.77 m on the same terrain is one
  van.height = 1.77f;
  CHECK(within_envelope(van, vans, kEndTolerance, kClasses));
  // Without terrain (150 per m^2, about 0.13 m spacing), posed as a van
  // standing where the saloon stands: its top is 1.25 m above the van's bottom.
  const ScanShape level =
      measure_scan(features_of(dense), van_on_ground, pose, -1.0f, 0.0f, kSigmaSurface, 150.0f);
  CHECK(level.height == doctest::Approx(1.25f).epsilon(0.01));
  CHECK_FALSE(within_envelope(level, vans, kEndTolerance, kClasses));
  // Posed as that van tilted 7 degrees to follow the saloon's slopes: in the
  // model's frame the scan spans 1.65 m of z (its length leans), in the
  // air's vertical still 1.05 m above its lowest row.
  RigidPose tilted = pose;
  tilted.rotation = pose.rotation * pitch_matrix(0.12f);
  const ScanShape leaning =
      measure_scan(features_of(dense), van_on_ground, tilted, -1.0f, 0.0f, kSigmaSurface, 150.0f);
  CHECK(leaning.height < 1.3f);
  CHECK_FALSE(within_envelope(leaning, vans, kEndTolerance, kClasses));
  // Posed as a van sunk 0.45 m so that the roofs meet: van-high, but the
  // van's lower 0.66 m holds no point, where the side's rows lie 0.1 m apart
  // (the allowance: 3 / sqrt(150) = 0.24 m).
  const blob::ModelRecord van_sunk = box_record(4.9f, 1.95f, -0.45f, 1.3f);
  const ScanShape sunk = measure_scan(features_of(dense), van_sunk, pose, -1.0f, 0.0f, kSigmaSurface, 150.0f);
  CHECK(sunk.height == doctest::Approx(1.70f).epsilon(0.01));
  CHECK(sunk.bottom_gap == doctest::Approx(0.66f).epsilon(0.03));
  CHECK_FALSE(within_envelope(sunk, vans, kEndTolerance, kClasses));
  // A fleet van itself at 60 per m^2 without terrain: its lowest row 0.3 m
  // up the side is within the allowance (3 / sqrt(60) = 0.39 m).
  const std::vector<float> sparse_van = seen_box(4.9f, 1.95f, 1.75f, 0.0f, 0.3f, 0.35f, pose);
  const ScanShape real_van =
      measure_scan(features_of(sparse_van), van_on_ground, pose, -1.0f, 0.0f, kSigmaSurface, 60.0f);
  CHECK(within_envelope(real_van, vans, kEndTolerance, kClasses));
  // The same scan at 20 per m^2 (below min_height_density): the allowance
  // (0.67 m) would let a van sunk under a saloon pass, so without terrain
  // the height counts as unmeasured; with its terrain the class holds.
  const ScanShape bare_sparse =
      measure_scan(features_of(sparse_van), van_on_ground, pose, -1.0f, 0.0f, kSigmaSurface, 20.0f);
  CHECK(bare_sparse.bottom_gap < 3.0f / std::sqrt(20.0f));
  CHECK_FALSE(within_envelope(bare_sparse, vans, kEndTolerance, kClasses));
  CHECK(within_envelope(
      measure_scan(features_of(sparse_van), van_on_ground, pose, 1.75f, 0.05f, kSigmaSurface, 20.0f), vans,
      kEndTolerance, kClasses));
  // The same van's roof alone (a steep view that misses the sides): its
  // height is not measured, and the class is not confirmed.
  const std::vector<float> roof = seen_box(4.9f, 1.95f, 1.75f, 0.0f, 1.7f, 0.35f, pose);
  CHECK_FALSE(
      within_envelope(measure_scan(features_of(roof), van_on_ground, pose, -1.0f, 0.0f, kSigmaSurface, 60.0f),
                      vans, kEndTolerance, kClasses));
}

TEST_CASE("longer, wider or taller than every member is out; shorter (an occluded end) is not") {
  const ClassEnvelope vans = fleet_vans();
  ScanShape s;
  s.on_terrain = true;
  s.noise = 0.05f;
  s.spacing = 0.1f;
  s.length = 4.0f, s.width = 1.9f, s.height = 1.9f;
  CHECK(within_envelope(s, vans, kEndTolerance, kClasses));
  s.length = 2.5f;  // half hidden
  CHECK(within_envelope(s, vans, kEndTolerance, kClasses));
  s.length = vans.length_max + 2.0f * kEndTolerance + 0.05f;  // a truck's length
  CHECK_FALSE(within_envelope(s, vans, kEndTolerance, kClasses));
  s.length = 4.0f;
  s.width = vans.width_max + 2.0f * kEndTolerance + 0.05f;
  CHECK_FALSE(within_envelope(s, vans, kEndTolerance, kClasses));
  s.width = 1.9f;
  s.height = 2.9f;  // a truck's cab
  CHECK_FALSE(within_envelope(s, vans, kEndTolerance, kClasses));
  s.height = vans.height_max + 0.3f;  // within the top's noise (3 x 0.05) and the boxes' unseen bottom (0.2)
  CHECK(within_envelope(s, vans, kEndTolerance, kClasses));
}

TEST_CASE("a caller's terrain decides the class flag by the object's top above it") {
  const std::vector<double> model = test::toy_vehicle_points(1, 0.05f);  // toy-1, the pickup: 0.3-2.2 m
  const double t[3] = {-300.0, 80.0, 5.0};
  RecognizerConfig cfg;
  host::AlignedBytes ws(required_workspace_bytes(cfg));
  Recognizer rec;
  REQUIRE(rec.init(&test::shared_toy_database().db, cfg, ws.data(), ws.size()) == Status::kOk);
  const std::vector<double> view = test::toy_airborne_query(model, 0.4, t, 0.02, 7);
  std::vector<float> xyz(view.size());
  for (size_t i = 0; i < view.size(); i += 3)  // relative to the toy's ground, as a scene's objects are
    for (size_t a = 0; a < 3; ++a) xyz[i + a] = static_cast<float>(view[i + a] - t[a]);
  const uint32_t n = static_cast<uint32_t>(xyz.size() / 3);
  const Result bare = rec.recognize(xyz.data(), n);
  REQUIRE(bare.status == Status::kOk);
  REQUIRE(bare.class_ranking[0].vehicle_class == static_cast<uint32_t>(VehicleClass::kPickup));
  CHECK(bare.class_confident);
  // Its top 2.2 m above the terrain: the pickup's own height.
  const Result measured = rec.recognize(xyz.data(), n, ObjectTerrain{2.2f, 0.05f});
  CHECK(measured.class_confident);
  CHECK(measured.ranking[0].model == bare.ranking[0].model);
  // The same points said to stand 0.8 m high: no pickup of the database is that low.
  const Result low = rec.recognize(xyz.data(), n, ObjectTerrain{0.8f, 0.05f});
  CHECK_FALSE(low.class_confident);
  CHECK(low.ranking[0].model == bare.ranking[0].model);  // the model ranking is untouched
  CHECK(low.confident == bare.confident);
}
