// The spinhash command end to end on built-in data: generate vehicles, build
// a database, inspect and verify it, scan a vehicle from the air in a random
// georeferenced pose, and recognise it with each mode (JSON Lines contract).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli_runner.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud_test_support.hpp"

using namespace spinhash::host::test;

namespace {

constexpr int kVehicles = 6;  // one of each of the first six families

struct Pipeline {
  TempDir dir{"cli-pipeline"};
  std::string meshes = dir.file("fleet"), db = dir.file("fleet.shdb");
  Pipeline() {
    REQUIRE(run_spinhash(dir, "generate --count " + std::to_string(kVehicles) + " -o " + shell_quoted(meshes))
                .exit_code == 0);
    CliRun b = run_spinhash(
        dir, "build --quiet --no-calibration -o " + shell_quoted(db) + " " + shell_quoted(meshes));
    INFO(b.err);
    REQUIRE(b.exit_code == 0);
  }
};

const Pipeline& pipeline() {
  static const Pipeline p;
  return p;
}

// Value of a numeric field of a flat JSON object, NaN when absent.
double json_field(const std::string& line, const std::string& key) {
  size_t at = line.find("\"" + key + "\":");
  return at == std::string::npos ? NAN : std::atof(line.c_str() + at + key.size() + 3);
}

}  // namespace

TEST_CASE("build writes a database that info describes and verify checks") {
  const Pipeline& p = pipeline();
  CliRun info = run_spinhash(p.dir, "info " + shell_quoted(p.db));
  REQUIRE(info.exit_code == 0);
  CHECK(contains(info.out, "models        6"));
  CHECK(contains(info.out, "sedan-00"));
  CHECK(contains(info.out, "10x10 bins, R = 1 m"));
  CliRun verify =
      run_spinhash(p.dir, "verify --quiet --queries 1 " + shell_quoted(p.db) + " " + shell_quoted(p.meshes));
  INFO(verify.err);
  CHECK(verify.exit_code == 0);
  CHECK(contains(verify.out, "integrity     ok"));
  CHECK(contains(verify.out, "self-recognition 6/6"));
}

TEST_CASE("a georeferenced airborne scan in a random pose is recognised with its pose, in every mode") {
  const Pipeline& p = pipeline();
  const std::string query = p.dir.file("truck-00.ply"), pose = p.dir.file("truck-00.pose");
  CliRun scan =
      run_spinhash(p.dir, "scan " + shell_quoted(p.meshes + "/truck-00.obj") + " -o " + shell_quoted(query) +
                              " --noise 0.05 --seed 11 --random-pose --offset 500000 4000000 120"
                              " --pose-out " +
                              shell_quoted(pose));
  REQUIRE(scan.exit_code == 0);
  Eigen::Matrix4d truth;
  std::string error;
  REQUIRE(spinhash::host::read_pose(pose, &truth, &error));
  for (const char* mode : {"bran", "sran", "sind"}) {
    CliRun r = run_spinhash(p.dir, std::string("recognize --top 3 --mode ") + mode + " --db " +
                                       shell_quoted(p.db) + " " + shell_quoted(query));
    CAPTURE(mode);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.lines().size() == 1);
    const std::string line = r.lines()[0];
    CHECK(contains(line, "{\"query\":\"truck-00\",\"status\":\"ok\",\"ranking\":[{\"model\":\"truck-00\""));
    CHECK(json_field(line, "hypotheses") >= (std::string(mode) == "sind" ? 0 : 1));
    if (std::string(mode) == "sind") {
      CHECK(contains(line, "\"pose\":null"));
      continue;
    }
    // pose: 16 numbers, row-major, model -> query; translation within 0.3 m of the truth at UTM magnitudes.
    size_t at = line.find("\"pose\":[");
    REQUIRE(at != std::string::npos);
    double m[16];
    const char* s = line.c_str() + at + 8;
    for (double& v : m) {
      v = std::strtod(s, const_cast<char**>(&s));
      ++s;  // ',' or ']'
    }
    CHECK(std::fabs(m[3] - truth(0, 3)) < 0.3);
    CHECK(std::fabs(m[7] - truth(1, 3)) < 0.3);
    CHECK(std::fabs(m[11] - truth(2, 3)) < 0.3);
    CHECK(m[15] == 1.0);
    double yaw = std::atan2(m[4], m[0]), true_yaw = std::atan2(truth(1, 0), truth(0, 0));
    CHECK(std::fabs(std::remainder(yaw - true_yaw, 2 * M_PI)) < 0.1);
  }
}

TEST_CASE("scan writes LAS by the extension, ground classified, and recognize reads it") {
  const Pipeline& p = pipeline();
  const std::string query = p.dir.file("van-00.las");
  CliRun scan =
      run_spinhash(p.dir, "scan " + shell_quoted(p.meshes + "/van-00.obj") + " -o " + shell_quoted(query) +
                              " --noise 0.05 --seed 5 --random-pose --ground 3 --offset 431000 4020000 85");
  INFO(scan.err);
  REQUIRE(scan.exit_code == 0);
  std::string bytes, error;
  REQUIRE(spinhash::host::read_file(query, spinhash::host::kMaxCloudFileBytes, &bytes, &error));
  CHECK(bytes.rfind("LASF", 0) == 0);  // LAS, not a PLY under a .las name
  CliRun r = run_spinhash(p.dir, "recognize --top 2 --db " + shell_quoted(p.db) + " " + shell_quoted(query));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(contains(r.out, "{\"query\":\"van-00\",\"status\":\"ok\",\"ranking\":[{\"model\":\"van-00\""));

  CliRun unknown = run_spinhash(
      p.dir, "scan " + shell_quoted(p.meshes + "/van-00.obj") + " -o " + shell_quoted(p.dir.file("van.xyz")));
  CHECK(unknown.exit_code == 1);
  CHECK(contains(unknown.err, "unknown point-cloud extension (write .ply or .las)"));
}

TEST_CASE("scene finds the scanned vehicle on sloped ground, with a georeferenced pose and a picture") {
  const Pipeline& p = pipeline();
  const std::string tile = p.dir.file("tile-7.las"), pictures = p.dir.file("pictures");
  CliRun scan =
      run_spinhash(p.dir, "scan " + shell_quoted(p.meshes + "/truck-00.obj") + " -o " + shell_quoted(tile) +
                              " --seed 3 --random-pose --ground-slope 6 --offset 500000 4000000 120");
  INFO(scan.err);
  REQUIRE(scan.exit_code == 0);
  CliRun missing = run_spinhash(p.dir, "scene --db " + shell_quoted(p.db) + " --picture-out " +
                                           shell_quoted(pictures) + " " + shell_quoted(tile));
  CHECK(missing.exit_code == 2);  // the folder must exist: refused before any tile is read
  REQUIRE(std::system(("mkdir " + shell_quoted(pictures)).c_str()) == 0);
  CliRun r = run_spinhash(p.dir, "scene --db " + shell_quoted(p.db) + " --picture-out " +
                                     shell_quoted(pictures) + " " + shell_quoted(tile));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  int vehicles = 0;
  for (const std::string& line : r.lines()) {
    CHECK(contains(line, "{\"tile\":\"tile-7\",\"object\":"));
    if (!contains(line, "\"kind\":\"vehicle\"")) continue;
    ++vehicles;
    CHECK(contains(line, "\"model\":\"truck-00\""));
    CHECK(std::fabs(json_field(line, "time_ms")) > 0.0);
    // The pose is georeferenced: its translation lies near the offset, not near 0.
    const size_t at = line.find("\"center\":[");
    REQUIRE(at != std::string::npos);
    CHECK(std::fabs(std::atof(line.c_str() + at + 10) - 500000.0) < 30.0);
  }
  CHECK(vehicles == 1);
  std::string png, error;
  REQUIRE(spinhash::host::read_file(pictures + "/tile-7.png", 1u << 24, &png, &error));
  CHECK(png.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
  CHECK(png.size() > 1000);
}

TEST_CASE(
    "build gives each model its class: a manifest, then the folder's name, then the name's first word; "
    "a manifest may give a model of a class in no group its own group") {
  TempDir dir("cli-classes");
  const std::string gen = dir.file("gen");
  REQUIRE(run_spinhash(dir, "generate --count 3 -o " + shell_quoted(gen)).exit_code ==
          0);                                     // sedan, van, truck
  const std::string folder = dir.file("pickup");  // a folder named after a class
  std::filesystem::create_directories(folder);
  std::filesystem::rename(gen + "/van-00.obj", folder + "/hilux.obj");
  const std::string db = dir.file("c.shdb"), manifest = dir.file("classes.txt");
  write_bytes(manifest,
              "# model class [group]\ntruck-00 bus  # a manifest overrides the name\n"
              "sedan-00 other light  # an \"other\" vehicle, a light one\n"
              "hilux pickup light  # a class's own group, repeated\n");
  CliRun b = run_spinhash(dir, "build --quiet --no-calibration --classes " + shell_quoted(manifest) + " -o " +
                                   shell_quoted(db) + " " + shell_quoted(gen) + " " + shell_quoted(folder));
  INFO(b.err);
  REQUIRE(b.exit_code == 0);
  CliRun info = run_spinhash(dir, "info --format json " + shell_quoted(db));
  CHECK(contains(info.out, "{\"name\":\"sedan-00\",\"class\":\"other\",\"group\":\"light\""));
  CHECK(contains(info.out, "{\"name\":\"truck-00\",\"class\":\"bus\",\"group\":\"heavy\""));
  CHECK(contains(info.out, "{\"name\":\"hilux\",\"class\":\"pickup\",\"group\":\"light\""));
  write_bytes(manifest,
              "truck-00 lorry\nnobody sedan\nsedan-00\nhilux pickup heavy\nsedan-00 other big\n"
              "truck-00 other heavy extra\n");
  CliRun bad = run_spinhash(dir, "build --quiet --no-calibration --classes " + shell_quoted(manifest) +
                                     " -o " + shell_quoted(dir.file("bad.shdb")) + " " + shell_quoted(gen));
  CHECK(bad.exit_code == 1);
  CHECK(contains(bad.err, "classes.txt:1: unknown class 'lorry'"));
  CHECK(contains(bad.err, "classes.txt:2: no model named 'nobody'"));
  CHECK(contains(bad.err, "classes.txt:3: expected 'MODEL_NAME CLASS [GROUP]'"));
  CHECK(contains(bad.err,
                 "classes.txt:4: class 'pickup' is in group 'light': only a class in no group takes a group "
                 "per model"));
  CHECK(contains(bad.err, "classes.txt:5: unknown group 'big' (groups: none, light, heavy, armoured)"));
  CHECK(contains(bad.err, "classes.txt:6: expected 'MODEL_NAME CLASS [GROUP]'"));
}

TEST_CASE("recognize answers with a class ranking; a sparse scan names a class, never a model, confidently") {
  const Pipeline& p = pipeline();
  const std::string query = p.dir.file("sparse.ply");
  REQUIRE(run_spinhash(p.dir, "scan " + shell_quoted(p.meshes + "/truck-00.obj") + " -o " +
                                  shell_quoted(query) + " --random-pose --seed 4 --spacing 0.45")
              .exit_code == 0);
  CliRun r = run_spinhash(p.dir, "recognize --db " + shell_quoted(p.db) + " " + shell_quoted(query));
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  CHECK(contains(r.out, "\"class\":\"truck\""));
  CHECK(contains(r.out, "\"class_ranking\":[{\"class\":\"truck\""));
  CHECK(contains(r.out, "\"confident\":false"));  // a few points per m^2: not enough to name a model
}
