// The fit of the answer levels' thresholds (host-tools/db/calibration_fit)
// on synthetic calibration runs: the smallest threshold that reaches the
// target, thresholds that never increase with density (pooled bands), bands
// never confident for want of runs or of separation, and the outsider rate
// (unknown vehicles at the model level, clutter at every level).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "db/calibration_fit.hpp"
#include "db/tiny_blob.hpp"
#include "support/blob_patch.hpp"

using spinhash::AnswerLevel;
using spinhash::AnswerPass;
using spinhash::Database;
using spinhash::kCalibratedLevels;
using spinhash::level_index;
using spinhash::Status;
namespace blob = spinhash::blob;
namespace host = spinhash::host;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// A run whose every level has this evidence and rightness.
host::CalibrationRun run(host::RunKind kind, float density, float evidence, bool right) {
  host::CalibrationRun r;
  r.kind = kind;
  r.density = density;
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) r.evidence[l] = evidence, r.right[l] = right;
  return r;
}

host::FitOptions options(std::vector<float> edges, float target, uint32_t min_runs) {
  host::FitOptions o;
  o.band_edges = std::move(edges);
  o.target_precision = target;
  o.min_band_runs = min_runs;
  return o;
}

host::CalibrationContent fit(const std::vector<host::CalibrationRun>& runs, const host::FitOptions& o) {
  host::CalibrationContent c;
  std::string error;
  const bool ok = host::fit_calibration(runs, o, host::FitProvenance{}, &c, &error);
  CHECK_MESSAGE(ok, error);
  return c;
}

const blob::CalibrationCell& cell(const host::CalibrationContent& c, AnswerLevel level, uint32_t band) {
  return c.cells[level_index(level) * c.header.band_count + band];
}

// A tiny database's blob (native byte order) with the section `c`.
std::vector<uint8_t> tiny_blob_with(const host::CalibrationContent& c) {
  host::BlobContent content = host::make_tiny_blob_content(3, 20, 5);
  content.calibration = c;
  std::vector<uint8_t> bytes = spinhash::test::write_native(content);
  REQUIRE_FALSE(bytes.empty());
  return bytes;
}

}  // namespace

TEST_CASE("the threshold is the smallest evidence whose flagged runs are right with the target precision") {
  std::vector<host::CalibrationRun> runs;
  for (int e = 1; e <= 20; ++e)
    runs.push_back(run(host::RunKind::kKnown, 100.0f, static_cast<float>(e), true));
  for (float e : {0.5f, 1.5f, 2.5f, 8.5f}) runs.push_back(run(host::RunKind::kKnown, 100.0f, e, false));
  const host::CalibrationContent c = fit(runs, options({0.0f}, 0.9f, 5));
  REQUIRE(c.cells.size() == kCalibratedLevels);
  for (uint32_t l = 1; l <= kCalibratedLevels; ++l) {
    const blob::CalibrationCell& k = cell(c, static_cast<AnswerLevel>(l), 0);
    CAPTURE(l);
    CHECK(k.state == blob::kCellFitted);
    // At 2: 19 right of 21 flagged (0.905); at 1.5: 19 of 22 (0.864).
    CHECK(k.threshold == 2.0f);
    CHECK(k.precision == doctest::Approx(19.0 / 21.0));
    CHECK(k.recall == doctest::Approx(19.0 / 20.0));
    CHECK(k.positives == 20u);
    CHECK(k.negatives == 4u);
    CHECK(k.flagged == 21u);
  }
  CHECK(c.header.target_precision == 0.9f);
  CHECK(c.passes.size() == 1u);
  CHECK(c.passes[0].source == blob::kSourceFitted);
  CHECK(c.passes[0].runs == runs.size());
}

TEST_CASE("a denser band that would need more evidence is pooled with the sparser one") {
  std::vector<host::CalibrationRun> runs;
  for (int e = 1; e <= 10; ++e) {
    runs.push_back(run(host::RunKind::kKnown, 10.0f, static_cast<float>(e), true));
    runs.push_back(run(host::RunKind::kKnown, 100.0f, static_cast<float>(e), true));
  }
  runs.push_back(run(host::RunKind::kKnown, 10.0f, 0.5f, false));
  runs.push_back(run(host::RunKind::kKnown, 100.0f, 5.5f, false));
  runs.push_back(run(host::RunKind::kKnown, 100.0f, 4.5f, false));
  // Alone the sparse band flags from 0.5 (10 right of 11), the dense one
  // needs 6; pooled, 1 (20 right of 22; at 0.5, 20 of 23).
  const host::CalibrationContent c = fit(runs, options({0.0f, 50.0f}, 0.9f, 5));
  const blob::CalibrationCell& sparse = cell(c, AnswerLevel::kClass, 0);
  const blob::CalibrationCell& dense = cell(c, AnswerLevel::kClass, 1);
  REQUIRE(sparse.state == blob::kCellFitted);
  REQUIRE(dense.state == blob::kCellFitted);
  CHECK(sparse.threshold == 1.0f);
  CHECK(dense.threshold == 1.0f);
  CHECK(dense.precision == doctest::Approx(20.0 / 22.0));
  CHECK(sparse.recall == 1.0f);
  CHECK(sparse.positives == 10u);
  CHECK(sparse.negatives == 1u);
  CHECK(dense.negatives == 2u);
  CHECK(sparse.flagged == 10u);
  CHECK(dense.flagged == 12u);
}

TEST_CASE("too few runs, or no threshold that reaches the target, leave a band never confident") {
  std::vector<host::CalibrationRun> runs;
  for (int k = 0; k < 3; ++k)
    runs.push_back(run(host::RunKind::kKnown, 5.0f, 10.0f, true));  // band 0: 3 runs
  for (int k = 0; k < 6; ++k)
    runs.push_back(run(host::RunKind::kKnown, 30.0f, 10.0f + k, false));  // band 1: all wrong
  for (int e = 1; e <= 6; ++e)
    runs.push_back(run(host::RunKind::kKnown, 300.0f, static_cast<float>(e), true));
  const host::CalibrationContent c = fit(runs, options({0.0f, 20.0f, 200.0f}, 0.9f, 5));
  CHECK(cell(c, AnswerLevel::kModel, 0).state == blob::kCellTooFew);
  CHECK(cell(c, AnswerLevel::kModel, 0).positives == 3u);
  CHECK(cell(c, AnswerLevel::kModel, 1).state == blob::kCellUnreachable);
  CHECK(cell(c, AnswerLevel::kModel, 1).negatives == 6u);
  CHECK(cell(c, AnswerLevel::kModel, 1).threshold == 0.0f);
  CHECK(cell(c, AnswerLevel::kModel, 1).flagged == 0u);
  CHECK(cell(c, AnswerLevel::kModel, 2).state == blob::kCellFitted);
  CHECK(cell(c, AnswerLevel::kModel, 2).threshold == 1.0f);
  // Empty bands are too few runs as well.
  const host::CalibrationContent empty = fit({}, options({0.0f, 20.0f}, 0.9f, 5));
  for (const blob::CalibrationCell& k : empty.cells) CHECK(k.state == blob::kCellTooFew);
}

TEST_CASE("a sparse band fitted before a dense band never confident is pooled with it") {
  std::vector<host::CalibrationRun> runs;
  for (int e = 1; e <= 10; ++e)
    runs.push_back(run(host::RunKind::kKnown, 10.0f, static_cast<float>(e), true));
  for (int k = 0; k < 3; ++k)
    runs.push_back(run(host::RunKind::kKnown, 100.0f, 20.0f, true));  // too few alone
  const host::CalibrationContent c = fit(runs, options({0.0f, 50.0f}, 0.9f, 5));
  CHECK(cell(c, AnswerLevel::kGroup, 0).state == blob::kCellFitted);
  CHECK(cell(c, AnswerLevel::kGroup, 1).state == blob::kCellFitted);
  CHECK(cell(c, AnswerLevel::kGroup, 1).threshold == 1.0f);
}

TEST_CASE("failed prerequisites are never flagged; an unopposed lead only at the largest threshold") {
  std::vector<host::CalibrationRun> runs;
  for (int k = 0; k < 10; ++k) runs.push_back(run(host::RunKind::kKnown, 100.0f, kInf, true));
  for (int k = 0; k < 10; ++k) runs.push_back(run(host::RunKind::kKnown, 100.0f, 5.0f, false));
  for (int k = 0; k < 5; ++k) runs.push_back(run(host::RunKind::kKnown, 100.0f, -kInf, true));
  const host::CalibrationContent c = fit(runs, options({0.0f}, 0.99f, 5));
  const blob::CalibrationCell& k = cell(c, AnswerLevel::kModel, 0);
  REQUIRE(k.state == blob::kCellFitted);
  CHECK(k.threshold == std::numeric_limits<float>::max());
  CHECK(k.precision == 1.0f);
  CHECK(k.recall == doctest::Approx(10.0 / 15.0));
  CHECK(k.flagged == 10u);
}

TEST_CASE(
    "the model level flags at most (1 - target) / 2 of the unknown vehicles, the vehicle level of the "
    "clutter") {
  std::vector<host::CalibrationRun> runs;
  for (int e = 1; e <= 100; ++e)
    runs.push_back(run(host::RunKind::kKnown, 100.0f, static_cast<float>(e), true));
  // Unknown vehicles: right at every level but the model's (none of them is in the database).
  for (int k = 0; k < 100; ++k) {
    host::CalibrationRun unknown = run(host::RunKind::kUnknown, 100.0f, k == 0 ? 90.5f : -kInf, true);
    unknown.right[level_index(AnswerLevel::kModel)] = false;
    runs.push_back(unknown);
  }
  const host::CalibrationContent c = fit(runs, options({0.0f}, 0.99f, 5));
  // Precision alone would take 1 (100 right of 101); one unknown of 100 is
  // over the 0.5 % allowed, so the model level must pass it.
  CHECK(cell(c, AnswerLevel::kModel, 0).threshold == 91.0f);
  CHECK(cell(c, AnswerLevel::kClass, 0).threshold == 1.0f);
  // Clutter is the vehicle level's outsider: one tree above most vehicles.
  runs.push_back(run(host::RunKind::kClutter, 100.0f, 80.5f, false));
  const host::CalibrationContent with_tree = fit(runs, options({0.0f}, 0.99f, 5));
  CHECK(with_tree.cells[level_index(AnswerLevel::kVehicle)].threshold == 81.0f);
}

TEST_CASE("at the model level unknown runs count in the outsider rate alone, not in precision") {
  // 200 known runs right at 101-300 (800 more never pass the prerequisites),
  // 5 of 1 000 unknown runs just below: 0.5 %, as many as allowed. In
  // precision they would take it to 200 / 205.
  std::vector<host::CalibrationRun> runs;
  for (int k = 0; k < 1000; ++k)
    runs.push_back(
        run(host::RunKind::kKnown, 100.0f, k < 200 ? 101.0f + static_cast<float>(k) : -kInf, true));
  for (int k = 0; k < 1000; ++k) {
    host::CalibrationRun unknown = run(host::RunKind::kUnknown, 100.0f, k < 5 ? 100.5f : -kInf, true);
    unknown.right[level_index(AnswerLevel::kModel)] = false;
    runs.push_back(unknown);
  }
  const host::CalibrationContent c = fit(runs, options({0.0f}, 0.99f, 5));
  const blob::CalibrationCell& model = cell(c, AnswerLevel::kModel, 0);
  CHECK(model.threshold == 100.5f);
  CHECK(model.precision == 1.0f);
  CHECK(model.negatives == 1000u);
  CHECK(model.flagged == 205u);
}

TEST_CASE("unknown runs weigh as much as the known ones together") {
  // 40 known runs right at 10; 4 unknown runs, one of them wrong at 10:
  // unweighted 43 of 44 (0.977) would pass a 0.95 target, weighted
  // 40 + 30 of 80 (0.875) does not.
  std::vector<host::CalibrationRun> runs;
  for (int k = 0; k < 40; ++k) runs.push_back(run(host::RunKind::kKnown, 100.0f, 10.0f, true));
  for (int k = 0; k < 3; ++k) runs.push_back(run(host::RunKind::kUnknown, 100.0f, 10.0f, true));
  runs.push_back(run(host::RunKind::kUnknown, 100.0f, 10.0f, false));
  const host::CalibrationContent c = fit(runs, options({0.0f}, 0.95f, 5));
  CHECK(cell(c, AnswerLevel::kClass, 0).state == blob::kCellUnreachable);
}

TEST_CASE("the fit does not depend on the runs' order, and its section opens") {
  std::vector<host::CalibrationRun> runs;
  for (int k = 0; k < 400; ++k) {
    const float density = static_cast<float>(5 + (k * 37) % 400);
    const bool right = k % 13 != 0;
    runs.push_back(run(k % 3 == 0 ? host::RunKind::kUnknown : host::RunKind::kKnown, density,
                       static_cast<float>((k * 7919) % 101) * 0.1f + (right ? 1.0f : 0.0f), right));
  }
  const host::FitOptions o;  // the build's bands and target
  const host::CalibrationContent a = fit(runs, o);
  std::reverse(runs.begin(), runs.end());
  const host::CalibrationContent b = fit(runs, o);
  REQUIRE(a.cells.size() == b.cells.size());
  CHECK(std::memcmp(a.cells.data(), b.cells.data(), a.cells.size() * sizeof(blob::CalibrationCell)) == 0);
  spinhash::test::BlobPatch patch(tiny_blob_with(a));
  Database db;
  REQUIRE(patch.open(&db) == Status::kOk);
  CHECK(db.calibration().fitted(AnswerPass::kFull));
  CHECK(db.calibration().band_count() == o.band_edges.size());
}

TEST_CASE("each pass's table is fitted from its own runs alone") {
  // The full pass separates at 2, the first pass only at 6: the same scans
  // answered with less evidence.
  std::vector<host::CalibrationRun> runs;
  for (int e = 1; e <= 20; ++e) {
    host::CalibrationRun full = run(host::RunKind::kKnown, 100.0f, static_cast<float>(e), e >= 2);
    host::CalibrationRun first = run(host::RunKind::kKnown, 100.0f, static_cast<float>(e), e >= 6);
    first.pass = AnswerPass::kFirst;
    runs.push_back(full);
    runs.push_back(first);
  }
  const host::CalibrationContent c = fit(runs, options({0.0f}, 0.99f, 5));
  REQUIRE(c.passes.size() == 2u);
  CHECK(c.header.pass_count == 2u);
  CHECK(c.passes[0].pass == static_cast<uint32_t>(AnswerPass::kFull));
  CHECK(c.passes[1].pass == static_cast<uint32_t>(AnswerPass::kFirst));
  CHECK(c.passes[0].runs == 20u);
  CHECK(c.passes[1].runs == 20u);
  REQUIRE(c.cells.size() == 2u * kCalibratedLevels);
  CHECK(cell(c, AnswerLevel::kModel, 0).threshold == 2.0f);
  CHECK(c.cells[kCalibratedLevels + level_index(AnswerLevel::kModel)].threshold == 6.0f);
  spinhash::test::BlobPatch patch(tiny_blob_with(c));
  Database db;
  REQUIRE(patch.open(&db) == Status::kOk);
  CHECK(db.calibration().fitted(AnswerPass::kFirst));
  CHECK(db.calibration().confident(AnswerPass::kFull, AnswerLevel::kModel, 3.0f, 100.0f));
  CHECK_FALSE(db.calibration().confident(AnswerPass::kFirst, AnswerLevel::kModel, 3.0f, 100.0f));
  CHECK(db.calibration().confident(AnswerPass::kFirst, AnswerLevel::kModel, 6.0f, 100.0f));
}

TEST_CASE("the agree table: the first pass's evidence against a stop that loses nothing, no outsiders") {
  // Below evidence 10 the stop loses a right answer on every other run;
  // from 10 on it loses none, on known, left-out and clutter scans alike. A
  // full-pass table would hold the left-out and clutter runs at the model
  // level under the outsider rate and find no threshold; the stop has no
  // outsiders.
  std::vector<host::CalibrationRun> runs;
  const host::RunKind kinds[] = {host::RunKind::kKnown, host::RunKind::kUnknown, host::RunKind::kClutter};
  for (int e = 1; e <= 300; ++e) {
    host::CalibrationRun r = run(kinds[e % 3], 100.0f, static_cast<float>(e), e >= 10 || e % 2 == 0);
    r.pass = AnswerPass::kAgree;
    runs.push_back(r);
    host::CalibrationRun full = run(host::RunKind::kKnown, 100.0f, static_cast<float>(e), true);
    runs.push_back(full);
  }
  host::FitOptions o = options({0.0f}, 0.99f, 0);
  o.agree_precision = 0.995f;
  const host::CalibrationContent c = fit(runs, o);
  REQUIRE(c.passes.size() == 3u);  // the first pass without runs keeps its priors
  CHECK(c.passes[1].source == blob::kSourcePriors);
  CHECK(c.passes[2].pass == static_cast<uint32_t>(AnswerPass::kAgree));
  CHECK(c.passes[2].source == blob::kSourceFitted);
  CHECK(c.passes[2].runs == 300u);
  CHECK(c.passes[2].target_precision == 0.995f);
  CHECK(c.passes[0].target_precision == 0.0f);  // the header's
  const blob::CalibrationCell& model = c.cells[2u * kCalibratedLevels + level_index(AnswerLevel::kModel)];
  CHECK(model.state == blob::kCellFitted);
  CHECK(model.threshold <= 10.0f);
  CHECK(model.threshold > 1.0f);
  CHECK(model.precision >= 0.995f);
  spinhash::test::BlobPatch patch(tiny_blob_with(c));
  Database db;
  REQUIRE(patch.open(&db) == Status::kOk);
  CHECK(db.calibration().fitted(AnswerPass::kAgree));
  CHECK(db.calibration().target_precision(AnswerPass::kAgree) == 0.995f);
  CHECK(db.calibration().target_precision(AnswerPass::kFull) == 0.99f);
  CHECK(db.calibration().confident(AnswerPass::kAgree, AnswerLevel::kModel, 10.0f, 100.0f));
  CHECK_FALSE(db.calibration().confident(AnswerPass::kAgree, AnswerLevel::kModel, 1.0f, 100.0f));

  // Certainty asked of runs whose strongest pair disagrees: never confident.
  o.agree_precision = 1.0f;
  o.min_band_runs = 5;
  for (host::CalibrationRun& r : runs)
    if (r.pass == AnswerPass::kAgree && r.evidence[0] == 300.0f)
      for (bool& right : r.right) right = false;
  const host::CalibrationContent strict = fit(runs, o);
  CHECK(strict.cells[2u * kCalibratedLevels + level_index(AnswerLevel::kModel)].state ==
        blob::kCellUnreachable);
}

TEST_CASE("a section of the full pass alone leaves the first pass to its priors") {
  std::vector<host::CalibrationRun> runs;
  for (int e = 1; e <= 20; ++e)
    runs.push_back(run(host::RunKind::kKnown, 100.0f, static_cast<float>(e), true));
  const host::CalibrationContent c = fit(runs, options({0.0f}, 0.9f, 5));
  REQUIRE(c.passes.size() == 1u);
  spinhash::test::BlobPatch patch(tiny_blob_with(c));
  Database db;
  REQUIRE(patch.open(&db) == Status::kOk);
  CHECK(db.calibration().fitted(AnswerPass::kFull));
  CHECK_FALSE(db.calibration().fitted(AnswerPass::kFirst));
}

TEST_CASE("bad fit options are refused with a reason") {
  host::CalibrationContent c;
  std::string error;
  CHECK_FALSE(host::fit_calibration({}, options({1.0f}, 0.9f, 5), host::FitProvenance{}, &c, &error));
  CHECK(error.find("first 0") != std::string::npos);
  CHECK_FALSE(
      host::fit_calibration({}, options({0.0f, 5.0f, 5.0f}, 0.9f, 5), host::FitProvenance{}, &c, &error));
  CHECK_FALSE(host::fit_calibration({}, options({0.0f}, 0.0f, 5), host::FitProvenance{}, &c, &error));
  CHECK_FALSE(host::fit_calibration({},
                                    options(std::vector<float>(blob::kMaxDensityBands + 1u, 0.0f), 0.9f, 5),
                                    host::FitProvenance{}, &c, &error));
  CHECK(host::default_min_band_runs(0.99f) == 100u);
  CHECK(host::default_min_band_runs(0.9f) == 10u);
}
