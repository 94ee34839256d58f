// Golden vectors: every target opens the committed blob of its own byte
// order, recognises the committed queries and must reproduce the host's
// recorded ranking (tests/golden/README.md). The core is built with
// -ffp-contract=off, so the only float differences left come from each
// libm's expf/logf/acosf/...: scores may differ by a few units in the last
// place, never the ranking, feature counts or hypotheses.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "golden/golden_expected.hpp"
#include "spinhash/recognizer.hpp"
#include "support/golden_files.hpp"

using namespace spinhash;

namespace {

// Score tolerance: relative to the score's magnitude, floored at 1. Scores are
// sums of a few hundred log-terms computed in float; 1e-4 leaves room for
// last-place libm differences while any change of a hypothesis, inlier or
// pose shows up far above it.
constexpr double kScoreRelativeTolerance = 1e-4;
// Pose tolerance: rotation entries (unitless) and translation (m).
constexpr double kPoseTolerance = 1e-3;

bool score_close(float got, float want) {
  const double g = static_cast<double>(got), w = static_cast<double>(want);
  return std::fabs(g - w) <= kScoreRelativeTolerance * std::fmax(1.0, std::fabs(w));
}

}  // namespace

TEST_CASE("golden: the blob of this target's byte order reproduces the recorded rankings") {
  host::AlignedBytes blob = test::golden_blob(true);
  Database db;
  REQUIRE(Database::open(blob.data(), blob.size(), &db) == Status::kOk);
  const std::vector<float> xyz = test::golden_query_points();
  double worst_score = 0.0, worst_pose = 0.0;  // largest deviations seen, reported below

  for (size_t q = 0; q < sizeof(golden::kGoldenQueries) / sizeof(golden::kGoldenQueries[0]); ++q) {
    const golden::GoldenQuery& want = golden::kGoldenQueries[q];
    CAPTURE(q);
    RecognizerConfig cfg = golden::golden_config(want.mode);
    host::AlignedBytes workspace(required_workspace_bytes(cfg));
    Recognizer rec;
    REQUIRE(rec.init(&db, cfg, workspace.data(), workspace.size()) == Status::kOk);
    Result r = rec.recognize(xyz.data() + 3u * want.first_point, want.point_count);
    REQUIRE(r.status == Status::kOk);
    CHECK(r.stats.extract.features == want.features);
    CHECK(r.stats.draws.hypotheses == want.hypotheses);
    CHECK(r.stats.draws.budget_exhausted == want.budget_exhausted);
    REQUIRE(r.ranking_count == want.ranking_count);
    for (uint32_t i = 0; i < r.ranking_count && i < golden::kMaxGoldenRanked; ++i) {
      CAPTURE(i);
      CHECK(r.ranking[i].model == want.ranking[i].model);
      CHECK_MESSAGE(score_close(r.ranking[i].score, want.ranking[i].score), "score ", r.ranking[i].score,
                    " recorded ", want.ranking[i].score);
      const double w = static_cast<double>(want.ranking[i].score);
      worst_score = std::fmax(
          worst_score, std::fabs(static_cast<double>(r.ranking[i].score) - w) / std::fmax(1.0, std::fabs(w)));
    }
    const Pose& p = r.ranking[0].pose;
    for (int i = 0; i < 12; ++i) {
      const double got = i < 9 ? static_cast<double>(p.rotation[i]) : p.translation[i - 9];
      CHECK(std::fabs(got - want.pose[i]) <= kPoseTolerance);
      worst_pose = std::fmax(worst_pose, std::fabs(got - want.pose[i]));
    }
  }
  MESSAGE("largest deviation from the recording: score ", worst_score, " (relative), pose ", worst_pose);
}

TEST_CASE("golden: the blob of the other byte order is refused with kBlobWrongByteOrder") {
  host::AlignedBytes blob = test::golden_blob(false);
  Database db;
  CHECK(Database::open(blob.data(), blob.size(), &db) == Status::kBlobWrongByteOrder);
  CHECK_FALSE(db.is_open());
}
