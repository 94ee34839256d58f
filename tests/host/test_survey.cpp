// spinhash survey end to end: a generated scene cut into 2 x 2 adjacent LAS
// tiles with vehicles across the cuts gives the whole scene's vehicles, each
// once; the same files for any --jobs; resume after an interruption without
// duplicates; GeoJSON and GeoPackage that other tools open. Plus the plan's
// rules (ownership, task text) and PROJ's footprint in WGS 84.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud/crs_resolve.hpp"
#include "cloud/las_writer.hpp"
#include "cloud_test_support.hpp"
#include "csv_columns.hpp"
#include "pipeline/database_file.hpp"
#include "survey/footprint.hpp"
#include "survey/gpkg_writer.hpp"
#include "survey/survey_runner.hpp"
#include "survey/task.hpp"
#include "survey/tile_run.hpp"

using namespace spinhash::host::test;
namespace survey = spinhash::survey;

namespace {

spinhash::host::Crs epsg_crs(uint32_t code) {
  spinhash::host::Crs c;
  c.horizontal_epsg = code;
  return spinhash::host::resolved(c);
}

constexpr int kKillWaitSteps = 6000;                 // polls for the first stored tile: 60 s at most
constexpr useconds_t kKillPollMicroseconds = 10000;  // 10 ms between polls

// scan-scene's default offset: the scene's centre, where the tiles meet.
constexpr double kCentreX = 512000.0, kCentreY = 5400000.0;
constexpr double kSameCentre = 0.01;  // m: a tile's object is the whole scene's to the centimetre

struct Detection {
  std::string model;
  double x = 0, y = 0;
};

std::string text_field(const std::string& line, const std::string& key) {
  const size_t at = line.find("\"" + key + "\":\"");
  if (at == std::string::npos) return "";
  const size_t start = at + key.size() + 4;
  return line.substr(start, line.find('"', start) - start);
}

std::vector<Detection> vehicles(const std::string& jsonl) {
  std::vector<Detection> v;
  std::istringstream in(jsonl);
  for (std::string line; std::getline(in, line);) {
    if (text_field(line, "kind") != "vehicle") continue;
    const size_t c = line.find("\"center\":[");
    REQUIRE(c != std::string::npos);
    Detection d;
    d.model = text_field(line, "model");
    d.x = std::atof(line.c_str() + c + 10);
    d.y = std::atof(line.c_str() + line.find(',', c + 10) + 1);
    v.push_back(d);
  }
  return v;
}

// The survey's vehicles are the whole scene's, each once: the same model
// at the same centre.
void check_each_once(const std::vector<Detection>& whole, const std::vector<Detection>& cut) {
  CHECK(cut.size() == whole.size());
  for (const Detection& w : whole) {
    int matches = 0;
    for (const Detection& c : cut)
      matches += std::hypot(c.x - w.x, c.y - w.y) < kSameCentre && c.model == w.model;
    CHECK_MESSAGE(matches == 1, w.model << " at " << w.x << " " << w.y);
  }
}

// Truth vehicles whose footprint a cut crosses.
int vehicles_across_cuts(const std::string& truth_csv) {
  const spinhash::host::test::CsvColumns truth(read_bytes(truth_csv));
  REQUIRE(truth.has("length"));
  int n = 0;
  for (size_t i = 0; i < truth.rows(); ++i) {
    if (truth.cell(i, "kind") != "vehicle") continue;
    const double half = 0.5 * truth.number(i, "length");
    n += std::fabs(truth.number(i, "center_x") - kCentreX) < half ||
         std::fabs(truth.number(i, "center_y") - kCentreY) < half;
  }
  return n;
}

void write_tiles(const std::string& scene, const std::string& dir) {
  std::vector<double> xyz;
  std::string error;
  REQUIRE_MESSAGE(spinhash::host::test::try_read_cloud(scene, &xyz, &error), error);
  std::vector<double> parts[4];
  for (size_t i = 0; i < xyz.size(); i += 3) {
    std::vector<double>& part = parts[2 * (xyz[i] >= kCentreX) + (xyz[i + 1] >= kCentreY)];
    part.insert(part.end(), xyz.begin() + static_cast<long>(i), xyz.begin() + static_cast<long>(i) + 3);
  }
  std::filesystem::create_directories(dir);
  for (int k = 0; k < 4; ++k)
    REQUIRE_MESSAGE(
        spinhash::host::write_las(dir + "/t" + std::to_string(k / 2) + std::to_string(k % 2) + ".las",
                                  parts[k], {}, &error),
        error);
}

struct Survey {
  TempDir dir{"survey"};
  std::string db = dir.file("fleet.shdb"), scene = dir.file("scene.las"), tiles = dir.file("tiles");
  std::string whole;  // `scene` on the uncut scene
  int across = 0;
  Survey() {
    REQUIRE(run_spinhash(dir, "generate --count 12 -o " + shell_quoted(dir.file("fleet"))).exit_code == 0);
    REQUIRE(run_spinhash(dir, "build --quiet --no-calibration -o " + shell_quoted(db) + " " +
                                  shell_quoted(dir.file("fleet")))
                .exit_code == 0);
    const CliRun s =
        run_spinhash(dir, "scan-scene " + shell_quoted(dir.file("fleet")) + " -o " + shell_quoted(scene) +
                              " --size 80 --vehicles 16 --trees 4 --seed 3");
    REQUIRE_MESSAGE(s.exit_code == 0, s.err);
    write_tiles(scene, tiles);
    const CliRun w = run_spinhash(dir, "scene --db " + shell_quoted(db) + " " + shell_quoted(scene));
    REQUIRE_MESSAGE(w.exit_code == 0, w.err);
    whole = w.out;
    across = vehicles_across_cuts(scene + ".truth.csv");
    const CliRun full = run("full", "--jobs 2");
    REQUIRE_MESSAGE(full.exit_code == 0, full.err);
  }
  CliRun run(const std::string& out, const std::string& flags) const {
    return run_spinhash(dir, "survey --quiet --db " + shell_quoted(db) + " --out " +
                                 shell_quoted(dir.file(out)) + " " + flags + " " + shell_quoted(tiles));
  }
  std::string output(const std::string& out, const std::string& name) const {
    return read_bytes(dir.file(out) + "/" + name);
  }
};

const Survey& generated() {
  static const Survey s;
  return s;
}

}  // namespace

TEST_CASE("survey: 2 x 2 tiles give the whole scene's vehicles, each once, the same for any --jobs") {
  const Survey& s = generated();
  REQUIRE(s.across >= 2);  // the seed puts vehicles across the cuts
  const std::vector<Detection> whole = vehicles(s.whole),
                               cut = vehicles(s.output("full", "detections.jsonl"));
  REQUIRE(whole.size() >= 12);
  check_each_once(whole, cut);
  const CliRun one = s.run("jobs1", "--jobs 1");
  REQUIRE(one.exit_code == 0);
  for (const char* f : {"detections.jsonl", "detections.geojson"})
    CHECK_MESSAGE(s.output("jobs1", f) == s.output("full", f), f);
  CHECK(contains(s.output("full", "survey.json"), "\"tiles_done\":4"));
}

TEST_CASE(
    "a sparse tile (5 points per m2): vehicles found whole at a coarser cell, the same by scene and survey") {
  const Survey& s = generated();
  const std::string sparse = s.dir.file("sparse.las"), tiles = s.dir.file("sparse-tiles");
  const CliRun made =
      run_spinhash(s.dir, "scan-scene " + shell_quoted(s.dir.file("fleet")) + " -o " + shell_quoted(sparse) +
                              " --size 80 --vehicles 16 --trees 4 --seed 3 --spacing 0.45");
  REQUIRE_MESSAGE(made.exit_code == 0, made.err);
  write_tiles(sparse, tiles);
  const CliRun whole = run_spinhash(s.dir, "scene --db " + shell_quoted(s.db) + " " + shell_quoted(sparse));
  REQUIRE_MESSAGE(whole.exit_code == 0, whole.err);
  CHECK(contains(whole.err, "segmentation cell 0.50 m"));
  const std::vector<Detection> found = vehicles(whole.out);
  CHECK(found.size() >= 8);  // of 16
  // From a finer cell two doublings reach 0.25 m only: a vehicle's points
  // then lie in cells that do not touch, and most vehicles fall apart.
  const CliRun fine = run_spinhash(
      s.dir, "scene --db " + shell_quoted(s.db) + " --segment-cell 0.0625 " + shell_quoted(sparse));
  REQUIRE_MESSAGE(fine.exit_code == 0, fine.err);
  CHECK(contains(fine.err, "segmentation cell 0.25 m"));
  CHECK(vehicles(fine.out).size() < found.size() / 2);
  const CliRun cut =
      run_spinhash(s.dir, "survey --quiet --jobs 2 --db " + shell_quoted(s.db) + " --out " +
                              shell_quoted(s.dir.file("sparse-out")) + " " + shell_quoted(tiles));
  REQUIRE_MESSAGE(cut.exit_code == 0, cut.err);
  CHECK(contains(read_bytes(s.dir.file("sparse-out") + "/survey.json"), "\"segment_cell_m\":0.5,"));
  const std::vector<Detection> tiled = vehicles(read_bytes(s.dir.file("sparse-out") + "/detections.jsonl"));
  check_each_once(found, tiled);
}

TEST_CASE("survey: the GeoJSON parses as a FeatureCollection, the GeoPackage opens, the overview is a PNG") {
  const Survey& s = generated();
  const std::string geo = s.dir.file("full") + "/detections.geojson";
  const size_t n = vehicles(s.output("full", "detections.jsonl")).size();
  const std::string check =
      "python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); "
      "assert d[\"type\"]==\"FeatureCollection\"; assert len(d[\"features\"])==int(sys.argv[2]); "
      "assert all(len(f[\"geometry\"][\"coordinates\"][0])==5 for f in d[\"features\"]); "
      "assert all(f[\"properties\"][\"level\"] in (\"none\",\"vehicle\",\"group\",\"class\",\"model\") "
      "and set(f[\"properties\"][\"levels\"])=={\"vehicle\",\"group\",\"class\",\"model\"} "
      "for f in d[\"features\"])' " +
      shell_quoted(geo) + " " + std::to_string(n);
  CHECK(std::system(check.c_str()) == 0);
  CHECK(strict_json_lines(s.dir, s.output("full", "detections.jsonl")));
  CHECK(s.output("full", "overview.png").substr(1, 3) == "PNG");
  if (std::system("command -v ogrinfo > /dev/null") == 0) {
    const std::string gpkg = s.dir.file("full") + "/detections.gpkg";
    const std::string info = "ogrinfo -so " + shell_quoted(gpkg) +
                             " detections | grep -q 'Feature Count: " + std::to_string(n) + "$'";
    CHECK(std::system(info.c_str()) == 0);
    // The answer levels: the level a text column, the levels a JSON one.
    for (const char* column : {"level: String", "levels: String", "group: String"}) {
      CAPTURE(column);
      const std::string has = "ogrinfo -so " + shell_quoted(gpkg) + " detections | grep -q '^" + column + "'";
      CHECK(std::system(has.c_str()) == 0);
    }
  }
}

TEST_CASE("survey --resume: an interrupted run loses nothing and a re-run duplicates nothing") {
  const Survey& s = generated();
  const std::string full = s.output("full", "detections.jsonl");
  SUBCASE("a tile's result lost in a crash (and a temporary left behind) is redone alone") {
    std::filesystem::copy(s.dir.file("full"), s.dir.file("crash"), std::filesystem::copy_options::recursive);
    std::filesystem::remove(s.dir.file("crash") + "/tile-results/t01.result");
    write_bytes(s.dir.file("crash") + "/tile-results/.t01.result.tmp.abc123", "half a result");
    const CliRun r = s.run("crash", "--resume");
    REQUIRE(r.exit_code == 0);
    CHECK(contains(s.output("crash", "survey.json"), "\"tiles_resumed\":3"));
    CHECK(s.output("crash", "detections.jsonl") == full);
    REQUIRE(s.run("crash", "--resume").exit_code == 0);  // nothing left to do: the same again
    CHECK(contains(s.output("crash", "survey.json"), "\"tiles_resumed\":4"));
    CHECK(s.output("crash", "detections.jsonl") == full);
  }
  SUBCASE("a result stored with other scene settings (another terrain rule, say) is run again") {
    std::filesystem::copy(s.dir.file("full"), s.dir.file("other"), std::filesystem::copy_options::recursive);
    const std::string stored = s.dir.file("other") + "/tile-results/t01.result";
    std::string text = read_bytes(stored);
    const size_t at = text.find(";scene=");
    REQUIRE(at != std::string::npos);
    text.replace(at + 7, 16, "0123456789abcdef");  // the digest of every scene_fields.h setting
    write_bytes(stored, text);
    const CliRun r = s.run("other", "--resume");
    REQUIRE(r.exit_code == 0);
    CHECK(contains(s.output("other", "survey.json"), "\"tiles_resumed\":3"));
    CHECK(s.output("other", "detections.jsonl") == full);
  }
  SUBCASE("a run that leaves out another class (--drop-class) runs every tile again") {
    std::filesystem::copy(s.dir.file("full"), s.dir.file("classes"),
                          std::filesystem::copy_options::recursive);
    const CliRun r = s.run("classes", "--resume --drop-class 200");  // a class no tile holds
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const std::string report = s.output("classes", "survey.json");
    CHECK(contains(report, "\"tiles_resumed\":0"));
    CHECK(contains(report, "\"dropped_classes\":[7,18,200]"));
    CHECK(s.output("classes", "detections.jsonl") == full);
  }
  SUBCASE("a run killed mid-way (SIGKILL after its first tile) is completed by --resume") {
    // Killed as soon as its first tile's result is stored: three tiles are
    // then left, whatever the machine's speed (a timer raced the run).
    const std::string results = s.dir.file("killed") + "/tile-results";
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 2);
      const std::string out = s.dir.file("killed");
      execl(SPINHASH_TEST_BINARY, "spinhash", "survey", "--quiet", "--jobs", "1", "--db", s.db.c_str(),
            "--out", out.c_str(), s.tiles.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    bool stored = false;
    for (int waited = 0; waited < kKillWaitSteps && !stored; ++waited) {
      std::error_code ec;
      for (const auto& e : std::filesystem::directory_iterator(results, ec))
        stored = stored || e.path().extension() == ".result";
      if (!stored) usleep(kKillPollMicroseconds);
    }
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    REQUIRE(stored);
    CHECK(WIFSIGNALED(status));  // killed before the end
    const CliRun r = s.run("killed", "--resume --jobs 2");
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(s.output("killed", "detections.jsonl") == full);
  }
  SUBCASE("an unreadable tile is refused with the reason; fixed, --resume completes the survey") {
    const std::string tile = s.tiles + "/t10.las", saved = read_bytes(tile);
    write_bytes(tile, saved.substr(0, 100));  // cut short: not even a header
    const CliRun broken = s.run("broken", "--jobs 2");
    write_bytes(tile, saved);
    CHECK(broken.exit_code == 3);
    CHECK(contains(broken.err, "t10.las"));
    CHECK(contains(s.output("broken", "survey.json"), "\"tiles_refused\":1"));
    CHECK(vehicles(s.output("broken", "detections.jsonl")).size() > 0);  // the other tiles' answers are kept
    const CliRun fixed = s.run("broken", "--resume --jobs 2");
    INFO(fixed.err);
    CHECK(fixed.exit_code == 0);
    CHECK(s.output("broken", "detections.jsonl") == full);
  }
}

TEST_CASE("survey: bad input has a clear message and exit status") {
  const Survey& s = generated();
  const CliRun missing = run_spinhash(s.dir, "survey --quiet --db " + shell_quoted(s.db) + " --out " +
                                                 shell_quoted(s.dir.file("bad")) + " " +
                                                 shell_quoted(s.dir.file("no-such-tile.las")));
  CHECK(missing.exit_code == 2);  // a usage error: docs/cli.md's rule
  CHECK(contains(missing.err, "no-such-tile.las"));
  const CliRun no_db =
      run_spinhash(s.dir, "survey --quiet --db " + shell_quoted(s.dir.file("none.shdb")) + " --out " +
                              shell_quoted(s.dir.file("bad")) + " " + shell_quoted(s.tiles));
  CHECK(no_db.exit_code == 2);
  CHECK(run_spinhash(s.dir, "survey --db x --out y --jobs 0 z").exit_code == 2);
  const CliRun no_class =
      run_spinhash(s.dir, "survey --db " + shell_quoted(s.db) + " --out " + shell_quoted(s.dir.file("bad")) +
                              " --drop-class 65,x " + shell_quoted(s.tiles));
  CHECK(no_class.exit_code == 2);
  CHECK(contains(no_class.err, "\"x\" is not a LAS class"));
  // A fresh run clears only its own stored results: --out over the folder
  // that holds the input tiles (DIR/tiles) leaves them alone.
  const CliRun here =
      run_spinhash(s.dir, "survey --quiet --jobs 2 --db " + shell_quoted(s.db) + " --out " +
                              shell_quoted(s.dir.path().string()) + " " + shell_quoted(s.tiles + "/t00.las"));
  CHECK(here.exit_code == 0);
  for (const char* t : {"t00", "t01", "t10", "t11"})
    CHECK(std::filesystem::exists(s.tiles + "/" + t + ".las"));
}

TEST_CASE("survey plan: ownership by half-open core, thin gaps to the nearest tile, holes to none") {
  survey::SurveyTask t;
  t.tile = {"b.las", "b", {{40.01, 0}, {80, 39.99}}};
  t.neighbours = {{"a.las", "a", {{0, 0}, {39.99, 39.99}}}};
  uint32_t self = 99;
  const std::vector<spinhash::OwnedArea> areas = survey::owner_areas(t, &self);  // path order: a, then b
  REQUIRE(areas.size() == 2u);
  CHECK(self == 1u);
  CHECK(areas[0].max[0] == 39.99);
  auto owner = [&](double x, double y) {
    return spinhash::owner_of(areas.data(), 2, x, y, survey::kGapTolerance);
  };
  CHECK(owner(10, 10) == 0u);
  CHECK(owner(39.995, 10) == 0u);  // in the gap, nearer a
  CHECK(owner(40.005, 10) == 1u);  // in the gap, nearer b
  CHECK(owner(40.0, 10) == 0u);    // a tie goes to the first path
  CHECK(owner(50, 10) == 1u);
  CHECK(owner(10, 45) == spinhash::kNoOwner);  // a hole: nobody's
  std::string error;
  survey::SurveyTask back;
  t.crs = "PROJCS[\"x\",\n\tUNIT[\"m\",1]]\\";
  t.key = "k";
  t.units.horizontal = t.units.vertical = 1200.0 / 3937.0;  // US survey feet reach the workers
  t.filter.named[65] = true;                                // --drop-class 65 reaches them too
  t.segment_cell = 0.5f;                                    // and the survey's segmentation cell
  REQUIRE(survey::parse_task_text(survey::task_text(t), &back, &error));
  CHECK(back.filter.classes() == std::vector<int>{7, 18, 65});
  CHECK(back.segment_cell == 0.5f);
  CHECK(back.units.horizontal == t.units.horizontal);
  CHECK(back.units.vertical == t.units.vertical);
  CHECK_FALSE(back.units.geographic);
  CHECK(back.tile.path == "b.las");
  CHECK(back.neighbours.size() == 1);
  CHECK(back.neighbours[0].core.max[0] == 39.99);
  CHECK(back.crs == t.crs);
  CHECK_FALSE(survey::parse_task_text("spinhash-survey-task 1\nindex 0\n", &back, &error));
}

TEST_CASE("survey footprint: a rectangle along the heading, in WGS 84 through PROJ") {
  spinhash::SceneObject o;
  o.center[0] = 500000.0, o.center[1] = 10.0;
  o.extent[0] = 4.0f, o.extent[1] = 2.0f;
  o.heading_deg = 90.0f;
  const survey::Ring r = survey::footprint(o);
  CHECK(r[0][0] == doctest::Approx(500001.0));  // heading +y: length along y
  CHECK(r[0][1] == doctest::Approx(8.0));
  CHECK(r[4] == r[0]);
  const survey::ToWgs84 utm33("EPSG:32633");  // UTM 33N: easting 500 000 is 15 degrees east
  const survey::Ring ll = utm33.transform(r);
  CHECK(ll[0][0] == doctest::Approx(15.0).epsilon(1e-4));
  CHECK(ll[0][1] == doctest::Approx(0.0).epsilon(1e-3));
  CHECK_THROWS(survey::ToWgs84("EPSG:999999"));
}

TEST_CASE(
    "survey with a CRS: lon/lat GeoJSON through PROJ, a GeoPackage in the tiles' CRS; mismatches refused") {
  const Survey& s = generated();
  spinhash::pipeline::DatabaseFile db;
  std::string error;
  REQUIRE_MESSAGE(spinhash::pipeline::load_database(s.db, &db, &error), error);
  survey::Catalogue cat = survey::read_catalogue({s.tiles + "/t00.las", s.tiles + "/t01.las"});
  REQUIRE(survey::check_catalogue(cat, {}, &error));
  std::vector<survey::SurveyTask> tasks = survey::plan_survey(cat, survey::kDefaultBuffer, "test");
  REQUIRE(tasks.size() == 2);
  tasks[0].crs = "EPSG:32633", tasks[0].crs_name = "EPSG:32633";  // as the LAS readers set it
  const survey::TileResult r = survey::run_task(db.db, tasks[0], survey::default_survey_scene());
  REQUIRE(!r.features.empty());
  // UTM 33N, E 512 km N 5400 km: about 15.16 E 48.75 N.
  const std::string& f = r.features[0];
  const double lon = std::atof(f.c_str() + f.find("[[[") + 3);
  const double lat = std::atof(f.c_str() + f.find(',', f.find("[[[")) + 1);
  CHECK(lon == doctest::Approx(15.16).epsilon(0.01));
  CHECK(lat == doctest::Approx(48.75).epsilon(0.01));
  CHECK(contains(f, "\"crs\":\"EPSG:32633\""));
  const std::string geo = s.dir.file("crs.geojson"), gpkg = s.dir.file("crs.gpkg");
  write_bytes(geo, "{\"type\":\"FeatureCollection\",\"features\":[" + f + "]}");
  REQUIRE_MESSAGE(survey::write_geopackage({f}, r.columns, gpkg, "EPSG:32633", &error), error);
  if (std::system("command -v ogrinfo > /dev/null") == 0)
    CHECK(std::system(
              ("ogrinfo -so " + shell_quoted(gpkg) + " detections | grep -q 'UTM zone 33N'").c_str()) == 0);

  survey::Catalogue mixed = cat;
  mixed.tiles[0].header.crs = epsg_crs(32633);
  REQUIRE(survey::check_catalogue(mixed, {}, &error));
  CHECK(mixed.crs.describe() == "EPSG:32633");
  REQUIRE(mixed.notes.size() == 1);  // t01 declares none: assumed to be in it, and said so
  CHECK(contains(mixed.notes[0], "t01"));
  mixed.tiles[1].header.crs = epsg_crs(25833);
  CHECK_FALSE(survey::check_catalogue(mixed, {}, &error));
  CHECK(contains(error, "do not share a CRS"));
}
