// The class level of an answer (recognize/classes.cpp): classes ranked by
// their best model, a class confident on less evidence than a model, and a
// model never confident on a sparse scan.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "geometry/normals.hpp"
#include "recognize/classes.hpp"
#include "recognize/confidence.hpp"
#include "spinhash/recognizer.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/grid_fixture.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kFeatures = 400;

// toy-0 (sedan), toy-5 (sedan), toy-1 (pickup), toy-4 (van): two sedans lead.
struct FourModels {
  RankedModel m[4];
  Result r;
  RankedClass classes[kVehicleClassCount];
  FourModels(float second_class_score) {
    const uint32_t models[4] = {0, 5, 1, 4};
    const float scores[4] = {-600.0f, -610.0f, second_class_score, second_class_score - 50.0f};
    for (int i = 0; i < 4; ++i) {
      m[i].model = models[i];
      m[i].score = scores[i];
      m[i].has_pose = true;
      m[i].inliers = 300;
    }
    r.ranking = m;
    r.ranking_count = 4;
    r.group_size = 2;
  }
};

const ExtentFit kPinned{0.05f, 0.05f};
constexpr float kDense = 200.0f;  // points per m^2 of the model's top

}  // namespace

TEST_CASE("classes are ranked by their best model, each once, with that model") {
  FourModels f(-700.0f);
  const uint32_t n = rank_classes(test::shared_toy_database().db, f.r, f.classes);
  REQUIRE(n == 3u);
  CHECK(f.classes[0].vehicle_class == static_cast<uint32_t>(VehicleClass::kSedan));
  CHECK(f.classes[0].score == -600.0f);
  CHECK(f.classes[0].model == 0u);
  CHECK(f.classes[0].best_rank == 0u);
  CHECK(f.classes[1].vehicle_class == static_cast<uint32_t>(VehicleClass::kPickup));
  CHECK(f.classes[1].best_rank == 2u);
  CHECK(f.classes[2].vehicle_class == static_cast<uint32_t>(VehicleClass::kVan));
  CHECK(f.classes[2].score == -750.0f);
}

TEST_CASE("a class is confident when it leads the next class by min_margin x sqrt(features)") {
  const RecognizerConfig cfg;
  const float margin = cfg.confidence.min_margin * std::sqrt(static_cast<float>(kFeatures));  // 24
  for (const float lead : {margin - 1.0f, margin + 1.0f}) {
    FourModels f(-600.0f - lead);
    f.r.class_ranking = f.classes;
    f.r.class_ranking_count = rank_classes(test::shared_toy_database().db, f.r, f.classes);
    CAPTURE(lead);
    // The two sedans are a look-alike group (no confident model), the class stands.
    CHECK(is_class_confident(f.r, cfg, kFeatures, kPinned, kDense) == (lead > margin));
  }
}

TEST_CASE("a class is never confident on little evidence, a poor fit, an overhang, alone or unclassified") {
  const RecognizerConfig cfg;
  FourModels f(-800.0f);
  f.r.class_ranking = f.classes;
  f.r.class_ranking_count = rank_classes(test::shared_toy_database().db, f.r, f.classes);
  REQUIRE(is_class_confident(f.r, cfg, kFeatures, kPinned, kDense));
  CHECK_FALSE(is_class_confident(f.r, cfg, kFeatures, kPinned, 4.0f));  // under 5 points per m^2
  CHECK_FALSE(is_class_confident(f.r, cfg, 11u, kPinned, kDense));      // under 12 features
  CHECK_FALSE(is_class_confident(f.r, cfg, kFeatures, ExtentFit{0.0f, 0.7f}, kDense));  // a larger vehicle
  f.m[0].inliers = 50;  // explains an eighth of the scan
  CHECK_FALSE(is_class_confident(f.r, cfg, kFeatures, kPinned, kDense));
  f.m[0].inliers = 300;
  RecognizerConfig sind = cfg;
  sind.mode = Mode::kSind;  // votes are no likelihoods
  CHECK_FALSE(is_class_confident(f.r, sind, kFeatures, kPinned, kDense));
  f.r.class_ranking_count = 1;  // no second class to tell it from
  CHECK_FALSE(is_class_confident(f.r, cfg, kFeatures, kPinned, kDense));
  f.r.class_ranking_count = 3;
  f.classes[0].vehicle_class = static_cast<uint32_t>(VehicleClass::kUnclassified);
  CHECK_FALSE(is_class_confident(f.r, cfg, kFeatures, kPinned, kDense));
}

TEST_CASE(
    "a ranked model explains the scan by the class level's tests of its own fit, not the class's margin") {
  const RecognizerConfig cfg;
  FourModels f(-605.0f);  // the classes lead by less than their margin
  f.r.class_ranking = f.classes;
  f.r.class_ranking_count = rank_classes(test::shared_toy_database().db, f.r, f.classes);
  REQUIRE_FALSE(is_class_confident(f.r, cfg, kFeatures, kPinned, kDense));
  // The group level asks it of any posed member: the second sedan, the pickup.
  CHECK(model_explains_scan(f.r, cfg, kFeatures, f.m[1], kPinned, kDense));
  CHECK(model_explains_scan(f.r, cfg, kFeatures, f.m[2], kPinned, kDense));
  // A box the scan stops 0.5 m short of (a shorter vehicle): past twice max_extent_shortfall.
  CHECK_FALSE(model_explains_scan(f.r, cfg, kFeatures, f.m[1], ExtentFit{0.5f, 0.0f}, kDense));
  CHECK(model_explains_scan(f.r, cfg, kFeatures, f.m[1], ExtentFit{0.35f, 0.0f}, kDense));
  f.m[2].has_pose = false;
  CHECK_FALSE(model_explains_scan(f.r, cfg, kFeatures, f.m[2], kPinned, kDense));
  f.m[3].inliers = 50;
  CHECK_FALSE(model_explains_scan(f.r, cfg, kFeatures, f.m[3], kPinned, kDense));
  CHECK_FALSE(model_explains_scan(f.r, cfg, kFeatures, f.m[1], kPinned, 4.0f));
}

TEST_CASE("scan density: points per m^2 of the part of the model's top the scan spans; a model needs 50") {
  blob::ModelRecord rec{};
  rec.bbox_min[0] = -2.0f, rec.bbox_max[0] = 2.0f;  // 4 x 2 m: 8 m^2
  rec.bbox_min[1] = -1.0f, rec.bbox_max[1] = 1.0f;
  rec.bbox_max[2] = 1.5f;
  RigidPose identity;
  identity.rotation.setIdentity();
  identity.translation.setZero();
  auto fit_of = [&](const std::vector<float>& corners) {
    QueryFeatures q;
    q.positions = corners.data();
    q.count = static_cast<uint32_t>(corners.size() / 3);
    return extent_fit(q, rec, identity);
  };
  // Features at the top's four corners, then at its rear half's (an
  // occluder hides the front: the scan is as dense where it shows the vehicle).
  const ExtentFit whole = fit_of({-2, -1, 1.5f, 2, 1, 1.5f, -2, 1, 1.5f, 2, -1, 1.5f});
  const ExtentFit rear = fit_of({-2, -1, 1.5f, 0, 1, 1.5f, -2, 1, 1.5f, 0, -1, 1.5f});
  CHECK(whole.seen_area == doctest::Approx(8.0f));
  CHECK(rear.seen_area == doctest::Approx(4.0f));
  RecognitionStats s;
  s.extract.points_in = 1000;
  s.ground.points_ground = 500;
  s.extract.points_nonfinite = 100;
  CHECK(scan_density(s, whole) == doctest::Approx(50.0f));
  CHECK(scan_density(s, rear) == doctest::Approx(100.0f));
  const RecognizerConfig cfg;
  const float min_density = cfg.confidence.min_model_density;
  CHECK(dense_enough_for_model(cfg, min_density));
  CHECK_FALSE(dense_enough_for_model(cfg, min_density - 1.0f));
  CHECK(min_density == 50.0f);    // above what most cars of a 10-30 per m^2 survey return
  s.ground.points_ground = 2000;  // more dropped than counted: no points, not a wrap-around
  CHECK(scan_density(s, whole) == 0.0f);
}

TEST_CASE("a recognised toy carries its class ranking; thinned to a sparse scan its model is not confident") {
  const std::vector<double> model = test::toy_vehicle_points(1, 0.05f);  // toy-1, a pickup
  const double t[3] = {-300.0, 80.0, 5.0};
  RecognizerConfig cfg;
  host::AlignedBytes ws(required_workspace_bytes(cfg));
  Recognizer rec;
  REQUIRE(rec.init(&test::shared_toy_database().db, cfg, ws.data(), ws.size()) == Status::kOk);
  const std::vector<double> dense = test::toy_airborne_query(model, 0.4, t, 0.02, 7);
  const Result r = rec.recognize(dense.data(), static_cast<uint32_t>(dense.size() / 3));
  REQUIRE(r.status == Status::kOk);
  REQUIRE(r.class_ranking_count >= 2u);
  CHECK(r.ranking[0].model == 1u);
  CHECK(r.confident);
  CHECK(r.class_ranking[0].vehicle_class == static_cast<uint32_t>(VehicleClass::kPickup));
  CHECK(r.class_ranking[0].model == 1u);
  CHECK(r.class_confident);
  for (uint32_t k = 1; k < r.class_ranking_count; ++k)
    CHECK(r.class_ranking[k].score <= r.class_ranking[k - 1].score);
  // Every 40th point: about 10 points per m^2 of the pickup's top.
  std::vector<double> sparse;
  for (size_t i = 0; i < dense.size(); i += 3 * 40)
    sparse.insert(sparse.end(), dense.begin() + i, dense.begin() + i + 3);
  const Result s = rec.recognize(sparse.data(), static_cast<uint32_t>(sparse.size() / 3));
  REQUIRE(s.status == Status::kOk);
  CAPTURE(s.stats.extract.points_in);
  CHECK_FALSE(s.confident);
}

TEST_CASE("the vehicle level needs what the group level needs: a posed member that explains the scan") {
  const std::vector<double> pickup = test::toy_vehicle_points(1, 0.05f);
  std::vector<double> stretched = pickup;  // 1.8 times as long: no toy's box fits it
  for (size_t i = 0; i < stretched.size(); i += 3) stretched[i] *= 1.8;
  const double t[3] = {40.0, -25.0, 3.0};
  RecognizerConfig cfg;
  host::AlignedBytes ws(required_workspace_bytes(cfg));
  Recognizer rec;
  REQUIRE(rec.init(&test::shared_toy_database().db, cfg, ws.data(), ws.size()) == Status::kOk);
  const auto evidence = [](const Result& r, AnswerLevel l) { return r.levels[level_index(l)].evidence; };
  const std::vector<double> a = test::toy_airborne_query(pickup, 0.4, t, 0.02, 3);
  const Result fits = rec.recognize(a.data(), static_cast<uint32_t>(a.size() / 3));
  REQUIRE(fits.status == Status::kOk);
  CHECK(std::isfinite(evidence(fits, AnswerLevel::kGroup)));
  CHECK(std::isfinite(evidence(fits, AnswerLevel::kVehicle)));
  CHECK(fits.levels[level_index(AnswerLevel::kVehicle)].confident);
  const std::vector<double> b = test::toy_airborne_query(stretched, 0.4, t, 0.02, 3);
  const Result long_one = rec.recognize(b.data(), static_cast<uint32_t>(b.size() / 3));
  REQUIRE(long_one.status == Status::kOk);
  REQUIRE(long_one.ranking_count > 0u);
  CHECK(long_one.ranking[0].has_pose);  // posed, but explained by no member
  CHECK_FALSE(std::isfinite(evidence(long_one, AnswerLevel::kGroup)));
  CHECK_FALSE(std::isfinite(evidence(long_one, AnswerLevel::kVehicle)));
  CHECK(long_one.level == AnswerLevel::kNone);
}

TEST_CASE("a sparse scan's normals come from a grown radius") {
  const FeatureParams fp;  // normal radius 0.4 m, as the databases
  ExtractorCapacity cap;
  host::AlignedBytes ws(1u << 24);
  Arena arena(ws.data(), ws.size());
  FeatureExtractor ex;
  REQUIRE(ex.init(fp, cap, arena) == Status::kOk);
  // 0.45 m between points: none has a neighbour within 0.4 m, every one
  // but the edges' has four within 0.6 m.
  const std::vector<float> box = test::box_surface(4.0f, 2.0f, 1.5f, 0.45f);
  const uint32_t n = static_cast<uint32_t>(box.size() / 3);
  test::GridFixture g(box, fp.normal_radius);
  std::vector<float> normals(box.size());
  std::vector<uint8_t> has(n);
  CHECK(estimate_normals(g.grid, box.data(), n, fp.normal_radius, normals.data(), has.data()) == 0u);
  CloudView cloud;
  cloud.xyz_f = box.data();
  cloud.count = n;
  FeatureSet fs;
  ExtractStats st;
  REQUIRE(ex.extract(cloud, OrientationHint{}, &fs, &st) == Status::kOk);
  CAPTURE(st.points_equalised);
  CHECK(static_cast<float>(st.points_oriented) >= 0.5f * static_cast<float>(st.points_equalised));
  CHECK(fs.count >= 20u);  // features to recognise it by
}
