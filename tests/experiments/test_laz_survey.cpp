// The same survey tiles as LAS and as LAZ give the same detections: a
// generated 80 m scene cut into 2 x 2 LAS tiles, each written again
// as LAZ by the benchmark writer (`spinhash-experiment laz-speed
// --write-format0-tile`, the only LAZ writer here; format 0 keeps x, y, z
// as the integers of the LAS twin), then `spinhash survey` on both folders.
#include "cli_runner.hpp"
#include "geometry_test_support.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

using namespace spinhash::host::test;

int run_experiment(const TempDir& dir, const std::string& args) {
  const std::string cmd =
      "'" SPINHASH_EXPERIMENT_BINARY "' " + args + " > /dev/null 2>> " + shell_quoted(dir.file("stderr.txt"));
  return std::system(cmd.c_str());
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("survey: LAZ tiles give the same detections as their LAS twins") {
  TempDir dir("laz-survey");
  const std::string fleet = dir.file("fleet"), db = dir.file("fleet.shdb");
  const std::string las = dir.file("las"), laz = dir.file("laz");
  REQUIRE(run_spinhash(dir, "generate --count 8 -o " + shell_quoted(fleet)).exit_code == 0);
  REQUIRE(
      run_spinhash(dir, "build --quiet --no-calibration -o " + shell_quoted(db) + " " + shell_quoted(fleet))
          .exit_code == 0);
  const CliRun scan = run_spinhash(
      dir, "scan-scene " + shell_quoted(fleet) + " -o " + shell_quoted(dir.file("scene.las")) +
               " --size 80 --vehicles 10 " + "--trees 3 --seed 5 --tiles-out " + shell_quoted(las));
  REQUIRE_MESSAGE(scan.exit_code == 0, scan.err);
  std::filesystem::create_directories(laz);
  int tiles = 0;
  for (const auto& e : std::filesystem::directory_iterator(las)) {
    const std::string twin = laz + "/" + e.path().stem().string() + ".laz";
    REQUIRE(run_experiment(dir, "laz-speed --min-seconds 0 --copies 1 --write-format0-tile " +
                                    shell_quoted(twin) + " --source " + shell_quoted(e.path().string())) ==
            0);
    ++tiles;
  }
  REQUIRE(tiles == 4);
  for (const std::string& in : {las, laz}) {
    const CliRun r = run_spinhash(dir, "survey --quiet --jobs 2 --db " + shell_quoted(db) + " --out " +
                                           shell_quoted(in + "-out") + " " + shell_quoted(in));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  }
  const std::string from_las = read_bytes(las + "-out/detections.jsonl");
  CHECK(count(from_las, "\"kind\":\"vehicle\"") >= 8);           // most of the 10: a real comparison
  CHECK(read_bytes(laz + "-out/detections.jsonl") == from_las);  // tiles are named by stem
  CHECK(read_bytes(laz + "-out/detections.geojson") == read_bytes(las + "-out/detections.geojson"));
}
