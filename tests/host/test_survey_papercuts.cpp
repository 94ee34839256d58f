// What a GIS user meets around `scene` and `survey`: files named for a
// format they are not, unreadable neighbours, progress and resume lines,
// the GeoPackage's schema, the overview's size and labels, interrupted runs'
// temporary folders, the exit-status rule and the help texts.
#include <doctest/doctest.h>
#include <gdal.h>
#include <ogr_api.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "cli_runner.hpp"
#include "cloud/las_writer.hpp"
#include "pipeline/json_line.hpp"
#include "pipeline/spill_folder.hpp"
#include "pipeline/tile_stream_order.hpp"
#include "render/survey_picture.hpp"

using namespace spinhash::host::test;
namespace fs = std::filesystem;

namespace {

const std::string kLas = SPINHASH_LAS_SAMPLES;
const std::string kLaz = SPINHASH_LAZ_SAMPLES;
constexpr int kExitUsage = 2, kExitCheckFailed = 3;
constexpr int kSpillWaitSteps = 3000;  // 10 ms polls: 30 s for a survey to start spilling

bool samples() {
  if (fs::is_directory(kLas) && fs::is_directory(kLaz)) return true;
  MESSAGE("samples not found beside the clone: skipped");
  return false;
}

struct Fixture {
  TempDir dir{"survey-papercuts"};
  std::string db = dir.file("fleet.shdb");
  Fixture() {
    const std::string meshes = dir.file("fleet");
    REQUIRE(run_spinhash(dir, "generate --count 2 -o " + shell_quoted(meshes)).exit_code == 0);
    REQUIRE(run_spinhash(dir,
                         "build --quiet --no-calibration -o " + shell_quoted(db) + " " + shell_quoted(meshes))
                .exit_code == 0);
  }
  CliRun run(const std::string& args) const { return run_spinhash(dir, args); }
};

const Fixture& fx() {
  static const Fixture f;
  return f;
}

std::string q(const std::string& s) { return shell_quoted(s); }

std::vector<std::string> spill_folders(const std::string& temp) {
  std::vector<std::string> v;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(temp, ec))
    if (e.path().filename().string().rfind(spinhash::pipeline::kSpillFolderPrefix, 0) == 0)
      v.push_back(e.path().string());
  return v;
}

}  // namespace

TEST_CASE("a text file named .laz is refused by its content, with one unreadable line, in scene and survey") {
  const Fixture& f = fx();
  TempDir dir("named-laz");
  const std::string fake = dir.file("listing.laz");
  write_bytes(fake, "x y z\n1 2 3\n4 5 6\n");
  const CliRun s = f.run("scene --db " + q(f.db) + " " + q(fake));
  CHECK(s.exit_code == kExitCheckFailed);
  REQUIRE(s.lines().size() == 1);
  CHECK(contains(s.lines()[0], "{\"tile\":\"listing\",\"status\":\"unreadable\""));
  CHECK(contains(s.out, "named .laz but not LAS/LAZ"));
  const CliRun v = f.run("survey --quiet --db " + q(f.db) + " --out " + q(dir.file("out")) + " " + q(fake));
  CHECK(v.exit_code == kExitCheckFailed);
  CHECK(contains(read_bytes(dir.file("out/survey.json")), "named .laz but not LAS/LAZ"));
}

TEST_CASE("points a file marks as noise are left out and said so by scene, recognize and survey.json") {
  if (!samples()) return;
  const Fixture& f = fx();
  TempDir dir("noise-points");
  const std::string tile = kLaz + "/crs/file_with_both_wkt_and_geotiff_vlrs.las";  // 25 points of class 7
  const std::string said = "25 points the file marks as noise (ASPRS classes 7 and 18) or withheld: left out";
  const CliRun s = f.run("scene --db " + q(f.db) + " " + q(tile));
  const CliRun r = f.run("recognize --db " + q(f.db) + " " + q(tile));
  CHECK(s.exit_code == 0);
  CHECK(r.exit_code == 0);
  CHECK(contains(s.err, said));
  CHECK(contains(r.err, said));
  const CliRun v =
      f.run("survey --quiet --jobs 1 --db " + q(f.db) + " --out " + q(dir.file("out")) + " " + q(tile));
  CHECK(v.exit_code == 0);
  const std::string report = read_bytes(dir.file("out/survey.json"));
  CHECK(contains(report, "\"points\":25383,\"buffer_points\":0,\"noise_points\":25,"));  // the tile's line
  CHECK(contains(report,
                 "\"buffer_points\":0,\"noise_points\":25,\"dropped_classes\":[7,18],\"segment_cell_m\":"));
}

TEST_CASE("a class the user names (--drop-class) is left out by scene, recognize and survey, and said so") {
  if (!samples()) return;
  const Fixture& f = fx();
  TempDir dir("drop-class");
  // A public format-8 sample whose producer put 539 low artefacts in class 65.
  const std::string tile = kLaz + "/no-twin/format8-nir-extrabytes.laz";
  const std::string said =
      "539 points the file marks as noise (ASPRS classes 7 and 18), withheld or of class 65, as asked: left "
      "out";
  const CliRun plain = f.run("scene --db " + q(f.db) + " " + q(tile));
  const CliRun s = f.run("scene --db " + q(f.db) + " --drop-class 65 " + q(tile));
  const CliRun r = f.run("recognize --db " + q(f.db) + " --drop-class 65 " + q(tile));
  CHECK(plain.exit_code == 0);
  CHECK_FALSE(contains(plain.err, "left out:"));
  CHECK(s.exit_code == 0);
  CHECK(contains(s.err, said));
  CHECK(contains(r.err, said));  // read as one query (a whole tile: no vehicle answer, exit 3)
  CHECK(contains(plain.err, "points 37805,"));
  CHECK(contains(s.err, "points 37266,"));
  const CliRun v = f.run("survey --quiet --jobs 1 --db " + q(f.db) + " --out " + q(dir.file("out")) +
                         " --drop-class 65 " + q(tile));
  CHECK(v.exit_code == 0);
  const std::string report = read_bytes(dir.file("out/survey.json"));
  CHECK(contains(report, "\"noise_points\":539,"));
  CHECK(contains(report, "\"dropped_classes\":[7,18,65]"));
  for (const char* bad : {"--drop-class 256", "--drop-class x", "--drop-class=-1"}) {
    const CliRun b = f.run(std::string("scene --db ") + q(f.db) + " " + bad + " " + q(tile));
    CHECK(b.exit_code == 2);
    CHECK(contains(b.err, "is not a LAS class"));
  }
}

TEST_CASE("scene and recognize write the same unreadable line for a file they cannot read") {
  const Fixture& f = fx();
  TempDir dir("unreadable-line");
  const std::string bad = dir.file("bad.xyz");
  write_bytes(bad, "1 2\n");
  const CliRun s = f.run("scene --db " + q(f.db) + " " + q(bad));
  const CliRun r = f.run("recognize --db " + q(f.db) + " " + q(bad));
  CHECK(s.exit_code == kExitCheckFailed);
  CHECK(r.exit_code == kExitCheckFailed);
  REQUIRE(s.lines().size() == 1);
  REQUIRE(r.lines().size() == 1);
  CHECK(s.lines()[0].rfind("{\"tile\":\"bad\",\"status\":\"unreadable\",\"error\":", 0) == 0);
  CHECK(r.lines()[0].rfind("{\"query\":\"bad\",\"status\":\"unreadable\",\"error\":", 0) == 0);
  CHECK(s.lines()[0].substr(13) == r.lines()[0].substr(14));  // the same members after the name
  CHECK(strict_json_lines(dir, s.out));
}

TEST_CASE(
    "a tile refused for its unreadable neighbour says so and names it; refusals do not repeat the path") {
  if (!samples()) return;
  const Fixture& f = fx();
  TempDir dir("neighbour");
  const std::string good = dir.file("a.laz"), bad = dir.file("b.laz");
  std::string bytes = read_bytes(kLaz + "/twins/autzen_trim.laz");
  write_bytes(good, bytes);
  for (size_t i = 300000; i < 300400; ++i) bytes[i] = '\xff';  // a chunk of b decodes to garbage
  write_bytes(bad, bytes);
  const std::string out = dir.file("out");
  const CliRun r =
      f.run("survey --quiet --jobs 1 --db " + q(f.db) + " --out " + q(out) + " " + q(good) + " " + q(bad));
  CHECK(r.exit_code == kExitCheckFailed);
  const std::string report = read_bytes(out + "/survey.json");
  CHECK(contains(report, "\"path\":" + spinhash::pipeline::json_string(good) +
                             ",\"reason\":\"refused for its neighbour " + bad +
                             ", which cannot be read: LAZ:"));
  CHECK(contains(report, "\"path\":" + spinhash::pipeline::json_string(bad) + ",\"reason\":\"LAZ:"));
  CHECK_FALSE(contains(r.err, bad + ": " + bad));
  CHECK_FALSE(contains(r.err, good + ": " + good));
}

TEST_CASE(
    "survey progress counts every tile of survey.json, in rates that show; --resume says what it kept") {
  if (!samples()) return;
  const Fixture& f = fx();
  TempDir dir("progress");
  const std::string fake = dir.file("fake.las"), tile = kLas + "/versions/1.2_3.las", out = dir.file("out");
  write_bytes(fake, "not a las file\n");
  const CliRun r =
      f.run("survey --jobs 1 --db " + q(f.db) + " --out " + q(out) + " " + q(tile) + " " + q(fake));
  CHECK(r.exit_code == kExitCheckFailed);
  CHECK(contains(read_bytes(out + "/survey.json"), "\"tiles_total\":2"));
  CHECK(contains(r.err, "[survey] 2/2 tiles (1 refused), "));
  CHECK_FALSE(contains(r.err, "0.00 M points/s"));
  CHECK(contains(r.err, " points/s, "));
  const CliRun again = f.run("survey --resume --jobs 1 --db " + q(f.db) + " --out " + q(out) + " " + q(tile));
  CHECK(again.exit_code == 0);
  CHECK(contains(again.err, "kept 1 tile a previous run finished: 1.2_3"));
}

TEST_CASE("an empty survey's GeoPackage has its schema; its overview is small") {
  if (!samples()) return;
  const Fixture& f = fx();
  TempDir dir("empty-gpkg");
  const std::string out = dir.file("out");
  const CliRun r =
      f.run("survey --quiet --db " + q(f.db) + " --out " + q(out) + " " + q(kLas + "/versions/1.2_3.las"));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CHECK(fs::file_size(out + "/overview.png") < 64u * 1024u);
  GDALAllRegister();
  GDALDatasetH ds = GDALOpenEx((out + "/detections.gpkg").c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr,
                               nullptr, nullptr);
  REQUIRE(ds != nullptr);
  OGRLayerH layer = GDALDatasetGetLayerByName(ds, "detections");
  REQUIRE(layer != nullptr);
  CHECK(OGR_L_GetFeatureCount(layer, TRUE) == 0);
  CHECK(wkbFlatten(OGR_L_GetGeomType(layer)) == wkbPolygon);
  OGRFeatureDefnH defn = OGR_L_GetLayerDefn(layer);
  const auto field = [&](const char* name) {
    const int i = OGR_FD_GetFieldIndex(defn, name);
    REQUIRE_MESSAGE(i >= 0, name);
    return OGR_FD_GetFieldDefn(defn, i);
  };
  for (const char* json : {"pose", "center", "extent", "ranking", "class_ranking"}) {
    CAPTURE(json);
    CHECK(OGR_Fld_GetType(field(json)) == OFTString);
    CHECK(OGR_Fld_GetSubType(field(json)) == OFSTJSON);
  }
  CHECK(OGR_Fld_GetType(field("score")) == OFTReal);
  CHECK(OGR_Fld_GetType(field("heading_deg")) == OFTReal);
  CHECK(OGR_Fld_GetSubType(field("confident")) == OFSTBoolean);
  CHECK(OGR_Fld_GetType(field("points")) == OFTInteger64);
  CHECK(OGR_Fld_GetType(field("tile")) == OFTString);
  GDALClose(ds);
}

TEST_CASE("GDAL is loaded only by a command that writes a GeoPackage, not at every start") {
  TempDir dir("gdal-load");
  const std::string log = dir.file("loader.txt");
  const auto loads_gdal = [&](const std::string& args) {
    const std::string cmd = "LD_DEBUG=libs '" SPINHASH_TEST_BINARY "' " + args + " > /dev/null 2> " + q(log);
    CHECK(std::system(cmd.c_str()) != -1);
    return contains(read_bytes(log), "libgdal");
  };
  CHECK_FALSE(loads_gdal("--version"));
  if (!samples()) return;
  const Fixture& f = fx();
  CHECK_FALSE(loads_gdal("scene --db " + q(f.db) + " " + q(kLas + "/versions/1.2_3.las")));
  CHECK(loads_gdal("survey --quiet --db " + q(f.db) + " --out " + q(dir.file("out")) + " " +
                   q(kLas + "/versions/1.2_3.las")));
}

TEST_CASE("the overview's tile names never overlap, even for tiles that overlap") {
  spinhash::host::SurveyPictureTile a, b, c;
  a.min[0] = 0, a.min[1] = 0, a.max[0] = 100, a.max[1] = 100, a.name = "tile-a";
  b = a, b.name = "tile-b";
  c = a, c.max[0] = 120, c.name = "tile-c";
  const auto labels = spinhash::host::survey_tile_labels({a, b, c});
  REQUIRE(labels.size() == 3);
  for (size_t i = 0; i < labels.size(); ++i) {
    CHECK(labels[i][2] >= labels[i][0]);  // placed
    for (size_t j = 0; j < i; ++j) {
      const bool apart = labels[i][2] < labels[j][0] || labels[j][2] < labels[i][0] ||
                         labels[i][3] < labels[j][1] || labels[j][3] < labels[i][1];
      CHECK_MESSAGE(apart, i << " meets " << j);
    }
  }
}

TEST_CASE("spill folders of processes that no longer run are removed at the next start") {
  TempDir dir("stale-spill");
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  setenv("TMPDIR", dir.path().string().c_str(), 1);
  const pid_t child = fork();
  if (child == 0) {
    (void)spinhash::pipeline::make_spill_folder();  // and die without removing it
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  const std::string own = spinhash::pipeline::make_spill_folder();  // a running process's: kept
  REQUIRE(spill_folders(dir.path().string()).size() == 2);
  const spinhash::pipeline::StaleSpill stale = spinhash::pipeline::remove_stale_spill_folders();
  CHECK(stale.folders == 1);
  CHECK(spill_folders(dir.path().string()) == std::vector<std::string>{own});
  spinhash::pipeline::remove_spill_folder(own);
  if (old)
    setenv("TMPDIR", saved.c_str(), 1);
  else
    unsetenv("TMPDIR");
}

TEST_CASE("a survey stopped by SIGINT removes its spill folders and says what it kept") {
  if (!samples()) return;
  const Fixture& f = fx();
  TempDir dir("sigint");
  const std::string temp = dir.file("tmp"), out = dir.file("out"), err = dir.file("err.txt");
  const std::string dense = dir.file("dense.las");
  fs::create_directories(temp);
  // A tile many times the along-track order's memory budget (--order-memory),
  // so that it spills early and is still being read when stopped (tiles
  // within the budget are ordered in memory and make no folder).
  const size_t budget = spinhash::pipeline::kMinOrderMemoryPoints;
  const size_t side = 1024, points = size_t{1} << 18;
  std::vector<double> xyz;
  xyz.reserve(3 * points);
  for (size_t i = 0; i < points; ++i)
    xyz.insert(xyz.end(),
               {500000.0 + 0.1 * static_cast<double>(i % side),
                4000000.0 + 0.1 * static_cast<double>(i / side), 0.01 * static_cast<double>(i % 7)});
  std::string error;
  REQUIRE_MESSAGE(spinhash::host::write_las(dense, xyz, {}, &error), error);
  const std::string budget_text = std::to_string(budget);
  const pid_t child = fork();
  if (child == 0) {
    setenv("TMPDIR", temp.c_str(), 1);
    if (freopen(err.c_str(), "w", stderr) == nullptr) _exit(127);
    execl(SPINHASH_TEST_BINARY, SPINHASH_TEST_BINARY, "survey", "--quiet", "--jobs", "1", "--order-memory",
          budget_text.c_str(), "--db", f.db.c_str(), "--out", out.c_str(), dense.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  bool spilling = false;
  for (int i = 0; i < kSpillWaitSteps && !spilling; ++i) {
    spilling = !spill_folders(temp).empty();
    if (!spilling) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  REQUIRE(spilling);
  kill(child, SIGINT);
  int status = 0;
  waitpid(child, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 128 + SIGINT);
  CHECK(spill_folders(temp).empty());
  CHECK(contains(read_bytes(err), "interrupted (SIGINT): removed"));
  CHECK(contains(read_bytes(err), "--resume"));
}

TEST_CASE(
    "exit status: a missing database or survey folder is a usage error; a missing tile its unreadable line") {
  const Fixture& f = fx();
  TempDir dir("exit-rule");
  const std::string absent = dir.file("absent.shdb"), tile = dir.file("absent.las");
  for (const std::string& cmd :
       {"scene --db " + q(absent) + " " + q(tile), "recognize --db " + q(absent) + " " + q(tile),
        "survey --db " + q(absent) + " --out " + q(dir.file("o")) + " " + q(tile), "info " + q(absent),
        "verify " + q(absent) + " " + q(tile)}) {
    CAPTURE(cmd);
    const CliRun r = f.run(cmd);
    CHECK(r.exit_code == kExitUsage);
    CHECK(contains(r.err, "absent.shdb"));
    CHECK(contains(r.err, "--help"));
  }
  const CliRun folder =
      f.run("survey --db " + q(f.db) + " --out " + q(dir.file("o")) + " " + q(dir.file("nofolder")));
  CHECK(folder.exit_code == kExitUsage);
  const CliRun scene = f.run("scene --db " + q(f.db) + " " + q(tile));
  CHECK(scene.exit_code == kExitCheckFailed);
  CHECK(contains(scene.out, "{\"tile\":\"absent\",\"status\":\"unreadable\""));
}

TEST_CASE("--order-memory outside its range is a usage error naming the option, in scene and survey") {
  const Fixture& f = fx();
  TempDir dir("order-memory");
  const std::string tile = dir.file("tile.las");
  for (const std::string& cmd :
       {"scene --order-memory 100 --db " + q(f.db) + " " + q(tile),
        "survey --order-memory 100 --db " + q(f.db) + " --out " + q(dir.file("o")) + " " + q(f.db)}) {
    CAPTURE(cmd);
    const CliRun r = f.run(cmd);
    CHECK(r.exit_code == kExitUsage);
    CHECK(contains(r.err, "--order-memory"));
  }
  CHECK(contains(f.run("scene --help").out, "--order-memory"));
}

TEST_CASE("help texts name the formats each command reads and writes") {
  const Fixture& f = fx();
  CHECK(contains(f.run("scan --help").out, "PLY or LAS"));
  CHECK(contains(f.run("scene --help").out, "LAZ"));
  CHECK(contains(f.run("recognize --help").out, "LAZ"));
  CHECK(contains(f.run("survey --help").out, "--work-crs"));
}
