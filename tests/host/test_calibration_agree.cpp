// The agree pass's calibration record (calib/calibration_runs): a scan's
// first-pass evidence, right at a level exactly when the first pass's
// answer there is the full pass's, whatever the truth.
#include <doctest/doctest.h>

#include <limits>

#include "calib/calibration_runs.hpp"
#include "spinhash/calibration.hpp"

using namespace spinhash;

namespace {

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

TEST_CASE("agree record: the first pass's evidence, right where the two passes name the same") {
  const Answer first(3, 1, 0, 4.5f, 80.0f);
  const Answer full(3, 1, 0, 9.0f, 120.0f);
  const host::CalibrationRun r = calib::agree_record(host::RunKind::kKnown, first.result, full.result);
  CHECK(r.pass == AnswerPass::kAgree);
  CHECK(r.kind == host::RunKind::kKnown);
  CHECK(r.density == 80.0f);  // the first pass's: the stop decides on it
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
    CHECK(r.evidence[l] == 4.5f);
    CHECK(r.right[l]);
  }
}

TEST_CASE("agree record: a pair that disagrees is wrong at that level even when the first answer is right") {
  // The scan is of model 3 (class 1): the first pass names it, the full
  // pass a look-alike of the same class. The truth plays no part.
  const Answer first(3, 1, 0, 4.5f, 80.0f);
  const Answer full(5, 1, 0, 9.0f, 80.0f);
  check_right(calib::agree_record(host::RunKind::kKnown, first.result, full.result), true, true, true, false);

  // Both wrong the same way on a vehicle left out of the database, or on
  // clutter: they agree.
  const Answer look_alike(5, 2, 1, 1.0f, 30.0f);
  check_right(calib::agree_record(host::RunKind::kUnknown, look_alike.result, look_alike.result), true, true,
              true, true);

  // Another class and group: wrong at every level but the vehicle's.
  const Answer other(7, 4, 2, 9.0f, 80.0f);
  check_right(calib::agree_record(host::RunKind::kClutter, first.result, other.result), true, false, false,
              false);
}

TEST_CASE("agree record: a failed first pass is never flagged and agrees only with a failed full pass") {
  Answer failed(3, 1, 0, 4.5f, 80.0f);
  failed.result.status = Status::kWorkCapReached;
  const Answer full(3, 1, 0, 9.0f, 80.0f);
  const host::CalibrationRun r = calib::agree_record(host::RunKind::kKnown, failed.result, full.result);
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
    CHECK(r.evidence[l] == -std::numeric_limits<float>::infinity());
    CHECK_FALSE(r.right[l]);
  }
  Answer none(3, 1, 0, 4.5f, 80.0f);
  none.result.ranking_count = none.result.class_ranking_count = none.result.group_ranking_count = 0;
  Answer none_full = none;
  none_full.result.ranking = none_full.model;  // its own arrays, not the copy source's
  const host::CalibrationRun both =
      calib::agree_record(host::RunKind::kClutter, none.result, none_full.result);
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) CHECK(both.right[l]);
}
