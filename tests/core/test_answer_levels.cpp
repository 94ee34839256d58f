// The answer's level (recognize/level_evidence): the most specific
// confident level whose coarser levels are confident and consistent; the
// group ranking; the priors, which decide as the recognizer did before
// calibration; and the fitted table, which replaces them.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "db/tiny_blob.hpp"
#include "recognize/classes.hpp"
#include "recognize/level_evidence.hpp"
#include "support/blob_patch.hpp"

using spinhash::AnswerLevel;
using spinhash::AnswerPass;
using spinhash::Database;
using spinhash::level_index;
using spinhash::RankedClass;
using spinhash::RankedGroup;
using spinhash::RankedModel;
using spinhash::RecognizerConfig;
using spinhash::Result;
using spinhash::Status;
namespace blob = spinhash::blob;
namespace host = spinhash::host;

namespace {

// Tiny model i is of class 1 + i: sedan, van, pickup (light), truck, bus (heavy), tracked (armoured).
constexpr uint32_t kSedan = 0, kVan = 1, kTruck = 3, kTracked = 5;

struct Opened {
  std::vector<uint8_t> bytes;
  spinhash::test::BlobPatch patch;
  Database db;
  explicit Opened(const host::BlobContent& c) : bytes(spinhash::test::write_native(c)), patch(bytes) {
    REQUIRE(patch.open(&db) == Status::kOk);
  }
};

host::BlobContent six_models() { return host::make_tiny_blob_content(6, 20, 3); }

// A result ranking `models` (best first, scores 0, -1, -2, ...) with its
// class and group rankings, every level's flag as given.
struct Ranked {
  RankedModel models[6];
  RankedClass classes[spinhash::kVehicleClassCount];
  RankedGroup groups[spinhash::kVehicleGroupCount];
  Result r;
  Ranked(const Database& db, std::initializer_list<uint32_t> order, std::initializer_list<bool> flags) {
    uint32_t k = 0;
    for (uint32_t m : order) {
      models[k].model = m;
      models[k].score = -static_cast<float>(k);
      models[k].has_pose = true;
      ++k;
    }
    r.status = Status::kOk;
    r.ranking = models;
    r.ranking_count = k;
    r.class_ranking = classes;
    r.class_ranking_count = spinhash::rank_classes(db, r, classes);
    r.group_ranking = groups;
    r.group_ranking_count = spinhash::rank_groups(db, r, groups);
    uint32_t l = 0;
    for (bool f : flags) r.levels[l++].confident = f;
  }
};

}  // namespace

TEST_CASE("groups rank by their best model; a group's first model is the ranking's first of it") {
  Opened o(six_models());
  Ranked a(o.db, {kTruck, kSedan, kTracked, kVan}, {});
  REQUIRE(a.r.group_ranking_count == 3u);
  CHECK(a.r.group_ranking[0].group == static_cast<uint32_t>(spinhash::VehicleGroup::kHeavy));
  CHECK(a.r.group_ranking[1].group == static_cast<uint32_t>(spinhash::VehicleGroup::kLight));
  CHECK(a.r.group_ranking[1].model == kSedan);
  CHECK(a.r.group_ranking[1].best_rank == 1u);
  CHECK(a.r.group_ranking[2].group == static_cast<uint32_t>(spinhash::VehicleGroup::kArmoured));
  CHECK(a.r.group_ranking[2].score == -2.0f);
}

TEST_CASE("the level is the most specific confident one whose coarser levels are confident") {
  Opened o(six_models());
  const auto level = [&o](std::initializer_list<bool> flags) {
    Ranked a(o.db, {kSedan, kVan, kTruck}, flags);
    return spinhash::answer_level(o.db, a.r);
  };
  // Flags: vehicle, group, class, model.
  CHECK(level({false, true, true, true}) == AnswerLevel::kNone);
  CHECK(level({true, false, false, false}) == AnswerLevel::kVehicle);
  CHECK(level({true, false, true, true}) == AnswerLevel::kVehicle);
  CHECK(level({true, true, false, true}) == AnswerLevel::kGroup);
  CHECK(level({true, true, true, false}) == AnswerLevel::kClass);
  CHECK(level({true, true, true, true}) == AnswerLevel::kModel);
}

TEST_CASE("a level inconsistent with the coarser one does not count") {
  Opened o(six_models());
  Ranked a(o.db, {kSedan, kVan, kTruck}, {true, true, true, true});
  REQUIRE(spinhash::answer_level(o.db, a.r) == AnswerLevel::kModel);
  // The first class of another group than the first group's.
  a.classes[0].vehicle_class = static_cast<uint32_t>(spinhash::VehicleClass::kBus);
  CHECK(spinhash::answer_level(o.db, a.r) == AnswerLevel::kGroup);
  // The first model of another class than the first class.
  Ranked b(o.db, {kSedan, kVan, kTruck}, {true, true, true, true});
  b.classes[0].vehicle_class = static_cast<uint32_t>(spinhash::VehicleClass::kVan);
  CHECK(spinhash::answer_level(o.db, b.r) == AnswerLevel::kClass);
  // Nothing ranked at a level: the coarser one.
  Ranked c(o.db, {kSedan}, {true, true, true, true});
  c.r.group_ranking_count = 0;
  CHECK(spinhash::answer_level(o.db, c.r) == AnswerLevel::kVehicle);
}

TEST_CASE("the priors decide as the recognizer did before calibration") {
  const RecognizerConfig cfg;
  const float m = cfg.confidence.min_margin;
  // Model: no flag below min_model_density (50), the margin times sqrt(130 / density) below
  // full_model_density (130).
  CHECK_FALSE(spinhash::prior_confident(AnswerLevel::kModel, 1e30f, 49.0f, cfg));
  CHECK(spinhash::prior_confident(AnswerLevel::kModel, m, 200.0f, cfg));
  CHECK_FALSE(spinhash::prior_confident(AnswerLevel::kModel, m * 0.99f, 200.0f, cfg));
  CHECK(spinhash::prior_confident(AnswerLevel::kModel, m * std::sqrt(2.0f), 65.0f, cfg));
  CHECK_FALSE(spinhash::prior_confident(AnswerLevel::kModel, m * 1.4f, 65.0f, cfg));
  // Class and group: the margin at any density.
  CHECK(spinhash::prior_confident(AnswerLevel::kClass, m, 5.0f, cfg));
  CHECK_FALSE(spinhash::prior_confident(AnswerLevel::kClass, m * 0.99f, 500.0f, cfg));
  CHECK(spinhash::prior_confident(AnswerLevel::kGroup, m, 5.0f, cfg));
  // Failed prerequisites never pass.
  for (uint32_t l = 1; l <= spinhash::kCalibratedLevels; ++l)
    CHECK_FALSE(spinhash::prior_confident(static_cast<AnswerLevel>(l), spinhash::kNoEvidence, 500.0f, cfg));
  CHECK_FALSE(spinhash::prior_confident(AnswerLevel::kNone, 1e30f, 500.0f, cfg));
}

TEST_CASE("a fitted table replaces the priors") {
  host::BlobContent c = six_models();
  c.calibration.header.band_count = 2;
  c.calibration.header.band_min_density[1] = 100.0f;
  c.calibration.header.target_precision = 0.99f;
  c.calibration.passes[0].source = blob::kSourceFitted;
  c.calibration.passes[0].runs = 10;
  c.calibration.cells.assign(2 * spinhash::kCalibratedLevels, blob::CalibrationCell{});
  for (blob::CalibrationCell& k : c.calibration.cells) k.state = blob::kCellTooFew;
  blob::CalibrationCell& dense_model = c.calibration.cells[level_index(AnswerLevel::kModel) * 2 + 1];
  dense_model.state = blob::kCellFitted;
  dense_model.threshold = 0.3f;
  dense_model.precision = 1.0f;
  Opened o(c);
  const RecognizerConfig cfg;
  CHECK(spinhash::level_confident(o.db, AnswerPass::kFull, AnswerLevel::kModel, 0.3f, 150.0f, cfg));
  CHECK_FALSE(spinhash::level_confident(o.db, AnswerPass::kFull, AnswerLevel::kModel, 0.29f, 150.0f, cfg));
  CHECK_FALSE(spinhash::level_confident(o.db, AnswerPass::kFull, AnswerLevel::kModel, 1e30f, 50.0f, cfg));
  CHECK_FALSE(spinhash::level_confident(o.db, AnswerPass::kFull, AnswerLevel::kClass, 1e30f, 150.0f, cfg));
  Opened priors(six_models());
  CHECK(spinhash::level_confident(priors.db, AnswerPass::kFull, AnswerLevel::kClass,
                                  cfg.confidence.min_margin, 150.0f, cfg));
  CHECK_FALSE(
      spinhash::level_confident(priors.db, AnswerPass::kFull, AnswerLevel::kModel, 0.3f, 150.0f, cfg));
}

TEST_CASE("a model of a class in no group ranks, and answers, in its own group") {
  // Tiny model kTruck becomes an "other" vehicle: in no group, and then with
  // its own group, light (a buggy).
  host::BlobContent content = six_models();
  content.models[kTruck].vehicle_class = static_cast<uint8_t>(spinhash::VehicleClass::kOther);
  const auto light = static_cast<uint32_t>(spinhash::VehicleGroup::kLight),
             none = static_cast<uint32_t>(spinhash::VehicleGroup::kNone);
  {
    Opened o(content);
    Ranked a(o.db, {kTruck, kSedan}, {true, true, true, true});
    REQUIRE(a.r.group_ranking_count == 2u);
    CHECK(a.r.group_ranking[0].group == none);
    CHECK(spinhash::group_envelope(o.db, light).members == 3u);  // sedan, van, pickup
  }
  content.models[kTruck].vehicle_group = static_cast<uint8_t>(light);
  Opened o(content);
  Ranked a(o.db, {kTruck, kTracked, kSedan}, {true, true, true, true});
  REQUIRE(a.r.group_ranking_count == 2u);
  CHECK(a.r.group_ranking[0].group == light);
  CHECK(a.r.group_ranking[0].model == kTruck);
  CHECK(static_cast<uint32_t>(spinhash::model_group(o.db.model(kTruck))) == light);
  CHECK(spinhash::group_envelope(o.db, light).members == 4u);
  // The class "other" is in no group: its answer climbs through its best
  // model's group, so every level holds.
  CHECK(a.r.class_ranking[0].vehicle_class == static_cast<uint32_t>(spinhash::VehicleClass::kOther));
  CHECK(spinhash::answer_level(o.db, a.r) == AnswerLevel::kModel);
  // Its model's group not first: the class does not follow the group.
  Ranked b(o.db, {kTruck, kTracked, kSedan}, {true, true, true, true});
  b.groups[0].group = static_cast<uint32_t>(spinhash::VehicleGroup::kArmoured);
  CHECK(spinhash::answer_level(o.db, b.r) == AnswerLevel::kGroup);
}
