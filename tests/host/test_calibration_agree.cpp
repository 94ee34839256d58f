// The agree pass's calibration record (calib/calibration_runs): a scan's
// first-pass evidence, wrong at a level only when the full pass names the
// truth there and the first pass does not (stopping would lose a right
// answer).
#include <doctest/doctest.h>

#include <limits>

#include "calib/calibration_runs.hpp"
#include "spinhash/calibration.hpp"
#include "spinhash/vehicle_class.hpp"

using namespace spinhash;

namespace {

constexpr uint32_t kSedan = static_cast<uint32_t>(VehicleClass::kSedan);
constexpr uint32_t kTruck = static_cast<uint32_t>(VehicleClass::kTruck);
const uint32_t kLight = static_cast<uint32_t>(vehicle_group_of(kSedan));
const uint32_t kHeavy = static_cast<uint32_t>(vehicle_group_of(kTruck));

// A result naming `model` of `vehicle_class` in `group` first, with evidence
// `evidence` at every level and scan density `density`.
struct Answer {
  RankedModel model[1];
  RankedClass vehicle_class[1];
  RankedGroup group[1];
  Result result;

  Answer(uint32_t m, uint32_t c, uint32_t g, float evidence, float density) {
    model[0].model = m;
    model[0].has_pose = true;
    vehicle_class[0].vehicle_class = c;
    group[0].group = g;
    result.status = Status::kOk;
    result.ranking = model;
    result.ranking_count = 1;
    result.class_ranking = vehicle_class;
    result.class_ranking_count = 1;
    result.group_ranking = group;
    result.group_ranking_count = 1;
    for (LevelAnswer& l : result.levels) l.evidence = evidence;
    result.stats.confidence.scan_density = density;
  }
};

// The run's rightness at vehicle, group, class and model.
void check_right(const host::CalibrationRun& r, bool vehicle, bool group, bool vehicle_class, bool model) {
  CHECK(r.right[level_index(AnswerLevel::kVehicle)] == vehicle);
  CHECK(r.right[level_index(AnswerLevel::kGroup)] == group);
  CHECK(r.right[level_index(AnswerLevel::kClass)] == vehicle_class);
  CHECK(r.right[level_index(AnswerLevel::kModel)] == model);
}

}  // namespace

TEST_CASE(
    "agree record: the first pass's evidence; right when both passes "
    "name the truth") {
  const Answer first(3, kSedan, kLight, 4.5f, 80.0f);
  const Answer full(3, kSedan, kLight, 9.0f, 120.0f);
  const host::CalibrationRun r =
      calib::agree_record(host::RunKind::kKnown, first.result, full.result, 3, kSedan, kLight);
  CHECK(r.pass == AnswerPass::kAgree);
  CHECK(r.kind == host::RunKind::kKnown);
  CHECK(r.density == 80.0f);  // the first pass's: the stop decides on it
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) CHECK(r.evidence[l] == 4.5f);
  check_right(r, true, true, true, true);
}

TEST_CASE(
    "agree record: wrong only where the full pass names the truth and "
    "the first pass does not") {
  // A sedan, model 3: the first pass names a look-alike of its class, the
  // full pass the sedan. Stopping loses the model.
  const Answer look_alike(5, kSedan, kLight, 4.5f, 80.0f);
  const Answer right(3, kSedan, kLight, 9.0f, 80.0f);
  check_right(calib::agree_record(host::RunKind::kKnown, look_alike.result, right.result, 3, kSedan, kLight),
              true, true, true, false);
  // The other way round the stop gains the model: nothing lost.
  check_right(calib::agree_record(host::RunKind::kKnown, right.result, look_alike.result, 3, kSedan, kLight),
              true, true, true, true);
  // Both wrong, even differently (a vehicle left out of the database, or
  // clutter): nothing to lose.
  const Answer truck(7, kTruck, kHeavy, 9.0f, 80.0f);
  check_right(
      calib::agree_record(host::RunKind::kUnknown, look_alike.result, truck.result, -1, kSedan, kLight), true,
      true, true, true);
  check_right(calib::agree_record(host::RunKind::kClutter, look_alike.result, truck.result, -1, 0u, 0u), true,
              true, true, true);
}

TEST_CASE(
    "agree record: a failed first pass is never flagged and loses what "
    "the full pass finds") {
  Answer failed(3, kSedan, kLight, 4.5f, 80.0f);
  failed.result.status = Status::kWorkCapReached;
  const Answer full(3, kSedan, kLight, 9.0f, 80.0f);
  const host::CalibrationRun r =
      calib::agree_record(host::RunKind::kKnown, failed.result, full.result, 3, kSedan, kLight);
  for (uint32_t l = 0; l < kCalibratedLevels; ++l)
    CHECK(r.evidence[l] == -std::numeric_limits<float>::infinity());
  check_right(r, true, false, false, false);
}

TEST_CASE("judge: a vehicle of a class in no group is judged by its model's own group") {
  // An "other" buggy whose model carries the light group: a light answer is
  // right at the group level, a heavy one wrong, and with no group of its
  // own (group none) no group answer is right.
  const uint32_t other = static_cast<uint32_t>(VehicleClass::kOther);
  const uint32_t none = static_cast<uint32_t>(VehicleGroup::kNone);
  REQUIRE(static_cast<uint32_t>(vehicle_group_of(other, kLight)) == kLight);
  const Answer light(5, other, kLight, 3.0f, 80.0f), heavy(5, other, kHeavy, 3.0f, 80.0f);
  bool right[kCalibratedLevels];
  calib::judge(light.result, false, 5, other, kLight, right);
  CHECK(right[level_index(AnswerLevel::kGroup)]);
  CHECK(right[level_index(AnswerLevel::kClass)]);
  CHECK(right[level_index(AnswerLevel::kModel)]);
  calib::judge(heavy.result, false, 5, other, kLight, right);
  CHECK_FALSE(right[level_index(AnswerLevel::kGroup)]);
  CHECK(right[level_index(AnswerLevel::kClass)]);
  calib::judge(light.result, false, 5, other, none, right);
  CHECK_FALSE(right[level_index(AnswerLevel::kGroup)]);
}
