// Smoke test of `spinhash-experiment accuracy` (the experiments themselves
// are too slow for CI): a 4-model run end to end, its CSVs and summary. CSV
// columns are read by name (csv_columns.hpp).
#include <doctest/doctest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "csv_columns.hpp"
#include "geometry_test_support.hpp"

namespace {

using spinhash::host::test::CsvColumns;
using spinhash::host::test::read_bytes;
using spinhash::host::test::TempDir;

// BRAN's rows of an accuracy run's per_query.csv, and those whose
// surface_coverage is a whole unoccluded top's (over 0.7, at most 1: the
// cascade's first pass, which answers these clear views, measures it on its
// 0.18 m features, which cover a top more coarsely than the full pass's)
// and whose scan_density is a 0.05 m scan's (hundreds of points per m^2 of the
// model's top). SIND's rows carry 0 for both: no pose.
struct BranRows {
  size_t rows = 0, covered = 0, dense = 0;
};
BranRows bran_rows(const CsvColumns& per_query) {
  BranRows r;
  for (size_t i = 0; i < per_query.rows(); ++i) {
    if (per_query.cell(i, "mode") != "bran") continue;
    const double coverage = per_query.number(i, "surface_coverage");
    r.rows += 1;
    r.covered += coverage > 0.7 && coverage <= 1.0 ? 1u : 0u;
    r.dense += per_query.number(i, "scan_density") > 100.0 ? 1u : 0u;
  }
  return r;
}

size_t count_lines(const std::string& text) {
  size_t n = 0;
  for (char c : text) n += c == '\n' ? 1u : 0u;
  return n;
}

// `spinhash-experiment scene` on one tiny 30 m tile per condition, at 0.15 m
// and 5 cm noise around a level reference, with ARGS; its stderr in DIR.
std::string scene_command(const TempDir& dir, const std::string& out, const std::string& args) {
  return "'" SPINHASH_EXPERIMENT_BINARY
         "' scene --tiles 1 --size 30 --spacings 0.15 --noises 0.05 "
         "--ref-slope 0 --ref-spacing 0.15 " +
         args + " --out '" + out + "' 2> '" + dir.file("stderr.txt") + "'";
}

}  // namespace

TEST_CASE("experiment accuracy runs end to end on a tiny fleet") {
  TempDir dir("experiment-smoke");
  const std::string out = dir.file("acc");
  const std::string cmd = "'" SPINHASH_EXPERIMENT_BINARY
                          "' accuracy --models 4 --queries-per-model 1 "
                          "--noise 0.05 --occlusion 0 --modes bran,sind --max-k 3 --out '" +
                          out + "' 2> '" + dir.file("stderr.txt") + "'";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string curves = read_bytes(out + "/accuracy.csv");
  CHECK(curves.rfind("mode,noise,occlusion,ground,spacing,k,p_correct_within_k,queries\n", 0) == 0);
  CHECK(count_lines(curves) == 1u + 2u * 3u);  // header + 2 modes x k = 1..3
  const CsvColumns per_query(read_bytes(out + "/per_query.csv"));
  CHECK(per_query.rows() == 2u * 4u);  // 2 modes x 4 queries
  // The share of the first model's upward surface that the unoccluded scan
  // shows under BRAN's pose, and the scan's points per m^2 of that model's top.
  REQUIRE(per_query.has("surface_coverage"));
  REQUIRE(per_query.has("scan_density"));
  const BranRows bran = bran_rows(per_query);
  CHECK(bran.rows == 4u);
  CHECK(bran.covered == 4u);
  CHECK(bran.dense == 4u);
  const std::string summary = read_bytes(out + "/summary.md");
  CHECK(summary.find("# Accuracy") != std::string::npos);
  CHECK(summary.find("| noise 5 cm, occlusion 0% | BRAN |") != std::string::npos);
}

TEST_CASE("the per-query checks read columns by name: moved columns pass, swapped values fail") {
  const std::string header = "mode,name,rank,surface_coverage,scan_density\n";
  const BranRows right = bran_rows(CsvColumns(header + "bran,van-00,1,0.97,912\nsind,van-00,1,0,0\n"));
  CHECK(right.rows == 1u);
  CHECK(right.covered == 1u);
  CHECK(right.dense == 1u);
  // The same values with the two columns in the other order: the same reading.
  const BranRows moved =
      bran_rows(CsvColumns("mode,name,rank,scan_density,surface_coverage\nbran,van-00,1,912,0.97\n"));
  CHECK(moved.covered == 1u);
  CHECK(moved.dense == 1u);
  // The density written where the coverage belongs and the other way round
  // (an experiment that writes its columns in the wrong order): both fail.
  const BranRows swapped = bran_rows(CsvColumns(header + "bran,van-00,1,912,0.97\n"));
  CHECK(swapped.covered == 0u);
  CHECK(swapped.dense == 0u);
}

TEST_CASE("experiment accuracy: look-alike copies in the database, a sparser scan, calibration") {
  TempDir dir("experiment-lookalikes");
  const std::string out = dir.file("acc");
  const std::string cmd = "'" SPINHASH_EXPERIMENT_BINARY
                          "' accuracy --models 3 --lookalikes 5 --queries-per-model 1 "
                          "--noise 0.05 --occlusion 0 --spacing 0.1 --modes bran --max-k 3 --out '" +
                          out + "' 2> '" + dir.file("stderr.txt") + "'";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const CsvColumns per_query(read_bytes(out + "/per_query.csv"));
  REQUIRE(per_query.rows() == 3u);  // queries scan the 3 originals only
  for (size_t i = 0; i < per_query.rows(); ++i) CHECK(per_query.cell(i, "spacing") == "0.1");
  const std::string summary = read_bytes(out + "/summary.md");
  CHECK(summary.find("each with 5 look-alike copies") != std::string::npos);
  CHECK(summary.find("18 models") != std::string::npos);  // 3 originals + 15 copies in the plot title's count
  CHECK(summary.find("spacing 10 cm") != std::string::npos);
  CHECK(summary.find("## Confidence") != std::string::npos);
  const CsvColumns calibration(read_bytes(out + "/calibration.csv"));
  for (const char* column :
       {"mode", "condition", "queries", "right_first", "confident", "confident_right", "precision", "recall"})
    CHECK(calibration.has(column));
  REQUIRE(calibration.rows() == 2u);  // all conditions + the one condition
  CHECK(calibration.cell(0, "mode") == "bran");
  CHECK(calibration.cell(0, "condition") == "all");
  CHECK(calibration.cell(0, "queries") == "3");
}

TEST_CASE("experiment scene runs end to end on tiny tiles and scores them against their truth") {
  TempDir dir("experiment-scene");
  const std::string out = dir.file("scene");
  const std::string cmd =
      scene_command(dir, out, "--models 6 --vehicles 2 --unknown-vehicles 1 --slopes 0,10");
  REQUIRE(std::system(cmd.c_str()) == 0);
  const CsvColumns scene(read_bytes(out + "/scene.csv"));
  REQUIRE(scene.rows() == 2u + 1u + 1u);  // 2 slopes + 1 spacing + 1 noise
  // Each sweep's rows, the reference (slope 0) in every sweep: sweep, slope, spacing, noise, tiles, vehicles.
  std::string rows;
  for (size_t i = 0; i < scene.rows(); ++i)
    for (const char* column : {"sweep", "slope_deg", "spacing", "noise", "tiles", "vehicles"})
      rows += scene.cell(i, column) + (std::string(column) == "vehicles" ? "\n" : " ");
  CHECK(rows ==
        "slope 0 0.15 0.05 1 2\nslope 10 0.15 0.05 1 2\nspacing 0 0.15 0.05 1 2\nnoise 0 0.15 0.05 1 2\n");
  // Two database vehicles and one unknown per tile, in 2 conditions (the reference is run once).
  const CsvColumns per_object(read_bytes(out + "/per_object.csv"));
  CHECK(per_object.rows() == 2u * 3u);
  // The pair is side by side; on these easy tiles both database vehicles are found.
  size_t vehicles = 0, unknown = 0, found = 0;
  for (size_t i = 0; i < per_object.rows(); ++i) {
    const std::string kind = per_object.cell(i, "kind");
    unknown += kind == "unknown_vehicle" ? 1u : 0u;
    if (kind != "vehicle") continue;
    vehicles += 1;
    CHECK(per_object.cell(i, "side_by_side") == "1");
    found += per_object.cell(i, "found") == "1" ? 1u : 0u;
  }
  CHECK(vehicles == 4u);
  CHECK(unknown == 2u);
  CHECK(found == 4u);
  // Confident right answers on database vehicles are never false alarms.
  const std::string alarms = read_bytes(out + "/false_alarms.csv");
  CHECK(alarms.rfind("slope_deg,spacing,noise,tile,on,answer,", 0) == 0);
  CHECK(alarms.find(",vehicle,") == std::string::npos);
  const std::string summary = read_bytes(out + "/summary.md");
  CHECK(summary.find("# Scene: simulated airborne tiles") != std::string::npos);
  CHECK(summary.find("## Targets") != std::string::npos);
  CHECK(summary.find("| found | >= 95% | 100% (4) | **met** |") != std::string::npos);
}

TEST_CASE("experiment scene takes --set FIELD=VALUE and states it; an unknown field is refused") {
  TempDir dir("experiment-scene-set");
  const std::string out = dir.file("scene");
  const std::string base = "--models 3 --vehicles 2 --unknown-vehicles 0 --slopes 0";
  REQUIRE(std::system(
              scene_command(dir, out, base + " --set min_margin=3.5 --set max_tilt_deg=30").c_str()) == 0);
  const std::string summary = read_bytes(out + "/summary.md");
  CHECK(summary.find("min_margin 3.5;") != std::string::npos);
  CHECK(summary.find("max_tilt_deg 30;") != std::string::npos);
  CHECK(std::system(scene_command(dir, out, base + " --set no_such_field=1").c_str()) != 0);
}
