// verify's check of a fitted calibration (host-tools/calib/calibration_check):
// a level whose flagged runs are all right agrees with cells that expect
// every flag right, whatever the number of runs.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_writer.hpp"
#include "calib/calibration_check.hpp"
#include "db/tiny_blob.hpp"
#include "spinhash/database.hpp"

using namespace spinhash;

TEST_CASE("calibration check: every flag right agrees with cells that expect every flag right") {
  host::BlobContent content = host::make_tiny_blob_content(3, 20, 5);
  host::CalibrationContent& c = content.calibration;
  c = host::CalibrationContent{};
  c.header.pass_count = 1;
  c.header.level_count = kCalibratedLevels;
  c.header.band_count = 1;
  c.header.target_precision = 0.99f;
  c.header.scans_per_model = 1;
  c.passes.push_back(blob::CalibrationPass{0u, blob::kSourceFitted, 1u, 0.0f});
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
    blob::CalibrationCell cell{};
    cell.state = blob::kCellFitted;
    cell.threshold = 0.0f;
    cell.precision = 1.0f;
    cell.recall = 1.0f;
    cell.positives = 1u;
    cell.flagged = 1u;
    c.cells.push_back(cell);
  }
  host::AlignedBytes bytes;
  Database db;
  std::string error;
  REQUIRE_MESSAGE(host::open_content(content, &bytes, &db, &error), error);
  // Run counts at which the 99.9 % Wilson interval of an observed share of
  // 1 computes its upper end one ulp below 1 (15, 244) and at which it does not (16).
  for (uint32_t n : {15u, 16u, 244u}) {
    std::vector<host::CalibrationRun> runs(n);
    for (host::CalibrationRun& r : runs) {
      r.density = 100.0f;
      for (uint32_t l = 0; l < kCalibratedLevels; ++l) r.evidence[l] = 1.0f, r.right[l] = true;
    }
    CAPTURE(n);
    for (const calib::LevelCheck& k : calib::check_calibration(db.calibration(), AnswerPass::kFull, runs)) {
      CHECK(k.flagged == n);
      CHECK(k.wrong == 0u);
      CHECK(k.observed_precision == 1.0);
      CHECK(k.agrees);
    }
  }
}
