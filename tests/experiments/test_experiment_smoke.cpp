// Smoke test of `spinhash-experiment accuracy` (the experiments themselves
// are too slow for CI): a 4-model run end to end, its CSVs and summary.
#include "geometry_test_support.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <sstream>
#include <string>

namespace {

using spinhash::host::test::read_bytes;
using spinhash::host::test::TempDir;

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
  const std::string per_query = read_bytes(out + "/per_query.csv");
  CHECK(count_lines(per_query) == 1u + 2u * 4u);  // header + 2 modes x 4 queries
  // The last two columns: the share of the first model's upward surface that
  // the unoccluded scan shows under BRAN's pose, and the scan's points per m^2
  // of that model's top (both 0 for SIND: no pose).
  CHECK(per_query.find(",class_lead,surface_coverage,scan_density\n") != std::string::npos);
  size_t covered = 0, dense = 0;
  for (size_t at = per_query.find("\nbran,"); at != std::string::npos;
       at = per_query.find("\nbran,", at + 1)) {
    const size_t end = per_query.find('\n', at + 1);
    const size_t density_from = per_query.rfind(',', end) + 1;
    const size_t coverage_from = per_query.rfind(',', density_from - 2) + 1;
    const double coverage =
        std::atof(per_query.substr(coverage_from, density_from - 1 - coverage_from).c_str());
    const double density = std::atof(per_query.substr(density_from, end - density_from).c_str());
    covered += coverage > 0.8 && coverage <= 1.0 ? 1u : 0u;
    dense += density > 100.0 ? 1u : 0u;  // the experiment's 0.05 m spacing: hundreds per m^2
  }
  CHECK(covered == 4u);
  CHECK(dense == 4u);
  const std::string summary = read_bytes(out + "/summary.md");
  CHECK(summary.find("# Accuracy") != std::string::npos);
  CHECK(summary.find("| noise 5 cm, occlusion 0% | BRAN |") != std::string::npos);
}

TEST_CASE("experiment accuracy: look-alike copies in the database, a sparser scan, calibration") {
  TempDir dir("experiment-lookalikes");
  const std::string out = dir.file("acc");
  const std::string cmd = "'" SPINHASH_EXPERIMENT_BINARY
                          "' accuracy --models 3 --lookalikes 5 --queries-per-model 1 "
                          "--noise 0.05 --occlusion 0 --spacing 0.1 --modes bran --max-k 3 --out '" +
                          out + "' 2> '" + dir.file("stderr.txt") + "'";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string per_query = read_bytes(out + "/per_query.csv");
  CHECK(count_lines(per_query) == 1u + 3u);  // queries scan the 3 originals only
  CHECK(per_query.find(",0.1,") != std::string::npos);
  const std::string summary = read_bytes(out + "/summary.md");
  CHECK(summary.find("each with 5 look-alike copies") != std::string::npos);
  CHECK(summary.find("18 models") != std::string::npos);  // 3 originals + 15 copies in the plot title's count
  CHECK(summary.find("spacing 10 cm") != std::string::npos);
  CHECK(summary.find("## Confidence") != std::string::npos);
  const std::string calibration = read_bytes(out + "/calibration.csv");
  CHECK(calibration.rfind("mode,condition,queries,right_first,confident,confident_right,precision,recall,",
                          0) == 0);
  CHECK(count_lines(calibration) == 1u + 2u);  // all conditions + the one condition
  CHECK(calibration.find("bran,all,3,") != std::string::npos);
}

TEST_CASE("experiment scene runs end to end on tiny tiles and scores them against their truth") {
  TempDir dir("experiment-scene");
  const std::string out = dir.file("scene");
  const std::string cmd =
      scene_command(dir, out, "--models 6 --vehicles 2 --unknown-vehicles 1 --slopes 0,10");
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string scene = read_bytes(out + "/scene.csv");
  CHECK(scene.rfind("sweep,slope_deg,spacing,noise,tiles,vehicles,found,recall,top1,", 0) == 0);
  CHECK(count_lines(scene) == 1u + 2u + 1u + 1u);  // header + 2 slopes + 1 spacing + 1 noise
  CHECK(scene.find("\nslope,10,0.15,0.05,1,2,") != std::string::npos);
  CHECK(scene.find("\nnoise,0,0.15,0.05,1,2,") !=
        std::string::npos);  // the reference, run once, in every sweep
  // Two database vehicles and one unknown per tile, in 2 conditions (the reference is run once).
  const std::string per_object = read_bytes(out + "/per_object.csv");
  CHECK(count_lines(per_object) == 1u + 2u * 3u);
  CHECK(per_object.find(",unknown_vehicle,") != std::string::npos);
  // The pair is side by side; on these easy tiles both database vehicles are found.
  size_t found = 0;
  for (size_t at = 0; (at = per_object.find(",vehicle,", at)) != std::string::npos; ++at) {
    const size_t line_end = per_object.find('\n', at);
    const std::string line = per_object.substr(at, line_end - at);
    CHECK(line.find(",1,") != std::string::npos);  // side_by_side
    // kind,model,side_by_side,under_tree,points,found: the 5th field after kind
    size_t field = 0, pos = 0;
    for (; field < 5 && pos != std::string::npos; ++field) pos = line.find(',', pos + 1);
    found += line.compare(pos + 1, 2, "1,") == 0 ? 1u : 0u;
  }
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
