// Real surveys in their real coordinates (cloud/crs*.hpp,
// cloud/metric_source.hpp): the public sample files' CRSs read from EPSG
// codes, OGC and ESRI WKT and GeoKeys, compared by meaning, their units
// applied by `scene` and `survey` alike, degrees refused unless a projected
// CRS is named to work in. Reads the samples beside the clone.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cloud/crs_match.hpp"
#include "cloud/crs_resolve.hpp"
#include "cloud/metric_source.hpp"
#include "cloud/point_source.hpp"
#include "survey/catalogue.hpp"
#include "survey/footprint.hpp"

using namespace spinhash::host;
using namespace spinhash::host::test;
namespace survey = spinhash::survey;

namespace {

const std::string kLas = SPINHASH_LAS_SAMPLES;
const std::string kLaz = SPINHASH_LAZ_SAMPLES;
constexpr double kUsFoot = 1200.0 / 3937.0;  // m (EPSG 9003)
constexpr double kFoot = 0.3048;             // m (EPSG 9002)
constexpr size_t kAutzenObjects = 76;        // segmented in autzen_trim's 110 000 points (1 m cells)

bool samples() {
  if (std::filesystem::is_directory(kLas) && std::filesystem::is_directory(kLaz)) return true;
  MESSAGE("samples not found beside the clone: skipped");
  return false;
}

Crs header_crs(const std::string& path) { return read_cloud_header(path).crs; }

// The three spellings of NAD83(HARN) / New Mexico Central (ftUS).
const std::vector<std::string>& new_mexico() {
  static const std::vector<std::string> files = {
      kLas + "/4_6_crop.las",          // GeoKeys: EPSG 2903 (+ a vertical datum code)
      kLas + "/test1_4.las",           // OGC WKT with AUTHORITY["EPSG","2903"] and TOWGS84
      kLaz + "/twins/1_4_w_evlr.laz",  // the same WKT in a LAZ file with EVLRs
  };
  return files;
}

// A database of two generated vehicles, made once.
const std::string& database() {
  static TempDir dir("crs-files");
  static const std::string db = [] {
    const std::string meshes = dir.file("fleet"), path = dir.file("fleet.shdb");
    REQUIRE(run_spinhash(dir, "generate --count 2 -o " + shell_quoted(meshes)).exit_code == 0);
    REQUIRE(run_spinhash(
                dir, "build --quiet --no-calibration -o " + shell_quoted(path) + " " + shell_quoted(meshes))
                .exit_code == 0);
    return path;
  }();
  return db;
}

size_t line_count(const std::string& text) {
  size_t n = 0;
  for (char c : text) n += c == '\n' ? 1u : 0u;
  return n;
}

}  // namespace

TEST_CASE(
    "crs: autzen's ESRI WKT in feet is read (its GeoKeys are user-defined), and is EPSG:2994 by meaning") {
  if (!samples()) return;
  for (const char* f : {"/twins/autzen_trim.las", "/twins/autzen_trim.laz"}) {
    INFO(f);
    const Crs c = header_crs(kLaz + f);
    CHECK(c.known());
    CHECK(c.source == "wkt");
    CHECK(c.describe() == "NAD_1983_HARN_Lambert_Conformal_Conic");
    CHECK(c.units.horizontal == doctest::Approx(kFoot).epsilon(1e-12));
    CHECK(c.units.vertical == doctest::Approx(kFoot).epsilon(1e-12));
    Crs oregon;
    oregon.horizontal_epsg = 2994;  // NAD83(HARN) / Oregon GIC Lambert (ft)
    CHECK(same_crs(c, resolved(oregon)));
  }
}

TEST_CASE("crs: the three spellings of EPSG:2903 are one CRS; UTM 17N is another") {
  if (!samples()) return;
  for (const std::string& a : new_mexico())
    for (const std::string& b : new_mexico()) {
      CAPTURE(a);
      CAPTURE(b);
      CHECK(same_crs(header_crs(a), header_crs(b)));
    }
  for (const std::string& f : new_mexico()) {
    CAPTURE(f);
    const Crs c = header_crs(f);
    CHECK(c.describe() == "EPSG:2903");
    CHECK(c.units.horizontal == doctest::Approx(kUsFoot).epsilon(1e-12));
    CHECK_FALSE(same_crs(c, header_crs(kLaz + "/crs/utm17.las")));
  }
}

TEST_CASE("crs: a survey of the three spellings runs; two truly different CRSs are refused naming both") {
  if (!samples()) return;
  std::string error;
  survey::Catalogue same = survey::read_catalogue(new_mexico());
  REQUIRE_MESSAGE(survey::check_catalogue(same, {}, &error), error);
  CHECK(same.crs.describe() == "EPSG:2903");
  for (const survey::CatalogueTile& t : same.tiles) CHECK_MESSAGE(t.error.empty(), t.error);

  const std::string crop = kLas + "/4_6_crop.las", utm = kLaz + "/crs/utm17.las";
  survey::Catalogue mixed = survey::read_catalogue({crop, utm});
  CHECK_FALSE(survey::check_catalogue(mixed, {}, &error));
  CHECK(contains(error, crop));
  CHECK(contains(error, "EPSG:2903"));
  CHECK(contains(error, utm));
  CHECK(contains(error, "EPSG:32617"));

  // autzen's WKT beside NAD83 / UTM 10N GeoKeys: a CRS each, not "declares no CRS".
  const std::string autzen = kLaz + "/twins/autzen_trim.las", utm10 = kLaz + "/crs/autzen-utm10.las";
  survey::Catalogue oregon = survey::read_catalogue({autzen, utm10});
  CHECK_FALSE(survey::check_catalogue(oregon, {}, &error));
  CHECK(contains(error, "NAD_1983_HARN_Lambert_Conformal_Conic"));
  CHECK(contains(error, "EPSG:26910"));

  WorkCrs work;  // named: both reprojected into it
  REQUIRE_MESSAGE(crs_from_user("EPSG:32613", &work.crs, &error), error);
  work.named = true;
  survey::Catalogue reprojected = survey::read_catalogue({crop, utm});
  CHECK_MESSAGE(survey::check_catalogue(reprojected, work, &error), error);
}

TEST_CASE("crs: GeoKeys whose linear unit overrides the PCS's are read in that unit, where the data lies") {
  if (!samples()) return;
  // EPSG:32128 (Pennsylvania North, metres) with ProjLinearUnitsGeoKey US
  // survey feet: the coordinates are feet (libgeotiff and GDAL read them so).
  const Crs c = header_crs(kLaz + "/twins/point-version-1-point-wise.las");
  CHECK(c.units.horizontal == doctest::Approx(kUsFoot).epsilon(1e-12));
  CHECK(c.id_epsg == 0);  // no longer the registered CRS
  const survey::ToWgs84 to_wgs84(c.proj_definition());
  survey::Ring r;
  for (auto& p : r) p = {2483800.0, 366400.0};
  const survey::Ring ll = to_wgs84.transform(r);
  CHECK(ll[0][0] == doctest::Approx(-75.88).epsilon(1e-3));  // Pennsylvania, not the Atlantic
  CHECK(ll[0][1] == doctest::Approx(41.16).epsilon(1e-3));
}

TEST_CASE("crs: a geographic file is refused by the door unless a projected CRS is named; then reprojected") {
  if (!samples()) return;
  const std::string path = kLaz + "/crs/epsg_4326.las";
  try {
    (void)open_metric_source(path);
    FAIL("a file in degrees was read");
  } catch (const CloudError& e) {
    CHECK(contains(e.what(), "degrees"));
    CHECK(contains(e.what(), "--work-crs"));
  }
  WorkCrs work;
  std::string error;
  REQUIRE_MESSAGE(crs_from_user("EPSG:32615", &work.crs, &error), error);
  work.named = true;
  const std::unique_ptr<MetricSource> s = open_metric_source(path, work);
  CHECK(s->to_metres().reprojected());
  const CloudHeader& h = s->header();  // UTM 15N metres around 94.67 W 31.04 N
  CHECK(h.min[0] == doctest::Approx(339336.9).epsilon(1e-4));
  CHECK(h.min[1] == doctest::Approx(3434890.2).epsilon(1e-4));
  std::vector<double> xyz(3 * 16);
  REQUIRE(s->read(xyz.data(), 16) == 16);
  for (size_t i = 0; i < 16; ++i) {
    CHECK(xyz[3 * i] >= h.min[0] - 1e-6);
    CHECK(xyz[3 * i] <= h.max[0] + 1e-6);
  }
  CHECK_FALSE(crs_from_user("EPSG:999999", &work.crs, &error));
}

TEST_CASE("crs: autzen's objects in feet, the same through scene and through a survey of it alone") {
  if (!samples()) return;
  TempDir dir("crs-autzen");
  const std::string tile = kLaz + "/twins/autzen_trim.laz";
  const CliRun scene = run_spinhash(dir, "scene --db " + shell_quoted(database()) + " " + shell_quoted(tile));
  REQUIRE_MESSAGE(scene.exit_code == 0, scene.err);
  CHECK(line_count(scene.out) == kAutzenObjects);
  CHECK(contains(scene.err, "CRS NAD_1983_HARN_Lambert_Conformal_Conic (foot)"));
  CHECK(contains(scene.out, "\"crs\":\"NAD_1983_HARN_Lambert_Conformal_Conic\""));

  const std::string out = dir.file("survey");
  const CliRun s = run_spinhash(dir, "survey --quiet --jobs 1 --db " + shell_quoted(database()) + " --out " +
                                         shell_quoted(out) + " " + shell_quoted(tile));
  REQUIRE_MESSAGE(s.exit_code == 0, s.err);
  CHECK(line_count(read_bytes(out + "/detections.jsonl")) == kAutzenObjects);
  const std::string report = read_bytes(out + "/survey.json");
  CHECK(contains(report, "\"crs\":\"NAD_1983_HARN_Lambert_Conformal_Conic\""));
  CHECK(contains(report, "\"horizontal\":\"foot\""));
  CHECK_FALSE(contains(report, "declares no CRS"));
}
