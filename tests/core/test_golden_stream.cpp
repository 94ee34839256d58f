// The stream's golden vectors: every target pushes the recorded flight-line
// strip (tests/golden/golden_stream.i16) through SceneStream, whole and in
// 4 kB chunks, and must report the host's recorded objects
// (golden_stream_expected.hpp): the same windows, kinds, point counts, first
// models and confidence exactly; scores and centres within the tolerances of
// the golden queries (test_golden.cpp: last-place libm differences only).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "golden/golden_stream_expected.hpp"
#include "support/golden_files.hpp"
#include "support/golden_stream_run.hpp"

using namespace spinhash;

namespace {

constexpr double kScoreRelativeTolerance = 1e-4;  // as test_golden.cpp, floored at 1
constexpr double kCentreTolerance = 1e-3;         // m

constexpr size_t kRecordedObjects =
    sizeof(golden::kGoldenStreamObjects) / sizeof(golden::kGoldenStreamObjects[0]);

double score_deviation(float got, float want) {
  const double w = static_cast<double>(want);
  return std::fabs(static_cast<double>(got) - w) / std::fmax(1.0, std::fabs(w));
}

// Checks one run against the recording; returns the largest score and centre deviations.
void check_run(const test::GoldenStreamRun& run, double* worst_score, double* worst_centre) {
  REQUIRE(run.status == Status::kOk);
  CHECK(run.stats.points_pushed == golden::kGoldenStreamStats.points_pushed);
  CHECK(run.stats.windows == golden::kGoldenStreamStats.windows);
  CHECK(run.stats.objects_reported == golden::kGoldenStreamStats.objects_reported);
  CHECK(run.stats.objects_not_owned == golden::kGoldenStreamStats.objects_not_owned);
  REQUIRE(run.objects.size() == kRecordedObjects);
  for (size_t k = 0; k < kRecordedObjects; ++k) {
    const golden::GoldenObject &got = run.objects[k], &want = golden::kGoldenStreamObjects[k];
    CAPTURE(k);
    CHECK(got.row == want.row);
    CHECK(got.col == want.col);
    CHECK(got.kind == want.kind);
    CHECK(got.points == want.points);
    CHECK(got.model == want.model);
    CHECK(got.confident == want.confident);
    const double ds = score_deviation(got.score, want.score);
    CHECK_MESSAGE(ds <= kScoreRelativeTolerance, "score ", got.score, " recorded ", want.score);
    *worst_score = std::fmax(*worst_score, ds);
    for (int i = 0; i < 3; ++i) {
      const double dc = std::fabs(got.center[i] - want.center[i]);
      CHECK(dc <= kCentreTolerance);
      *worst_centre = std::fmax(*worst_centre, dc);
    }
  }
}

}  // namespace

TEST_CASE("golden stream: the recorded strip gives the recorded objects, whole and in 4 kB chunks") {
  host::AlignedBytes blob = test::golden_blob(true);
  Database db;
  REQUIRE(Database::open(blob.data(), blob.size(), &db) == Status::kOk);
  const std::vector<double> xyz = test::golden_stream_points();
  double worst_score = 0.0, worst_centre = 0.0;
  for (size_t chunk : {xyz.size() / 3, static_cast<size_t>(golden::kStreamChunkPoints)}) {
    CAPTURE(chunk);
    check_run(test::run_golden_stream(db, xyz, chunk), &worst_score, &worst_centre);
  }
  MESSAGE("largest deviation from the recording: score ", worst_score, " (relative), centre ", worst_centre,
          " m");
}
