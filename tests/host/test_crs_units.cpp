// Units of a file's CRS (cloud/crs_units.hpp): US state plane tiles in US
// survey feet are read as metres, and their objects come back in feet,
// exactly where the same tile in metres puts them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud/crs_resolve.hpp"
#include "cloud/crs_units.hpp"
#include "cloud/metric_source.hpp"
#include "cloud/point_source.hpp"
#include "cloud_test_support.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/object_units.hpp"
#include "pipeline/tile_stream.hpp"

using namespace spinhash;
using namespace spinhash::host;
using namespace spinhash::host::test;

namespace {

constexpr double kUsFoot = 1200.0 / 3937.0;  // m (EPSG 9003)
constexpr double kFoot = 0.3048;             // m (EPSG 9002)
const std::string kLas = SPINHASH_LAS_SAMPLES;
const std::string kLaz = SPINHASH_LAZ_SAMPLES;

Crs epsg(uint32_t horizontal, uint32_t vertical = 0) {
  Crs c;
  c.horizontal_epsg = horizontal;
  c.vertical_epsg = vertical;
  return c;
}

// x y z triples handed out in chunks, as a reader would.
class VectorSource final : public PointSource {
 public:
  explicit VectorSource(std::vector<double> xyz) : xyz_(std::move(xyz)) {
    header_.format = "test";
    header_.count_known = true;
    header_.point_count = xyz_.size() / 3;
  }
  const CloudHeader& header() const override { return header_; }
  size_t read(double* out, size_t max_points) override {
    const size_t n = std::min(max_points, xyz_.size() / 3 - next_);
    std::copy_n(xyz_.begin() + static_cast<long>(3 * next_), 3 * n, out);
    next_ += n;
    return n;
  }

 private:
  std::vector<double> xyz_;
  size_t next_ = 0;
  CloudHeader header_;
};

struct Found {
  std::string kind;
  int64_t model = -1;
  bool confident = false;
  double center[3];
  double translation[3];
};

std::vector<Found> objects_of(const Database& db, std::vector<double> xyz, const AxisUnits& units) {
  VectorSource source(std::move(xyz));
  pipeline::TileStreamOptions options;
  options.units = units;
  std::vector<Found> found;
  const pipeline::TileStreamResult r = pipeline::stream_tile(db, source, options, [&](const SceneObject& o) {
    Found f;
    f.kind = object_kind_name(o.kind);
    f.model = o.ranking_count > 0 ? static_cast<int64_t>(o.ranking[0].model) : -1;
    f.confident = o.confident;
    std::copy_n(o.center, 3, f.center);
    std::copy_n(o.ranking_count > 0 ? o.ranking[0].pose.translation : o.center, 3, f.translation);
    found.push_back(f);
  });
  CHECK(r.status == Status::kOk);
  return found;
}

}  // namespace

TEST_CASE("crs units: feet, US survey feet, metres and degrees from EPSG codes, compounds and GeoKeys") {
  const AxisUnits ftus = axis_units(epsg(2903));  // NAD83(HARN) / New Mexico Central (ftUS)
  CHECK(ftus.horizontal == doctest::Approx(kUsFoot).epsilon(1e-12));
  CHECK(ftus.vertical == doctest::Approx(kUsFoot).epsilon(1e-12));  // no vertical CRS: the plane's unit
  CHECK(ftus.notes.size() == 1);
  CHECK(contains(ftus.describe(), "US survey foot"));

  const AxisUnits mixed = axis_units(epsg(2903, 5703));  // heights in NAVD88 metres
  CHECK(mixed.horizontal == doctest::Approx(kUsFoot).epsilon(1e-12));
  CHECK(mixed.vertical == 1.0);

  CHECK(axis_units(epsg(32617)).metric());  // UTM 17N
  CHECK(axis_units(epsg(32617)).describe().empty());
  const AxisUnits degrees = axis_units(epsg(4326));
  CHECK(degrees.geographic);
  CHECK(contains(degrees.describe(), "reproject"));

  Crs user_defined;  // a GeoKeys projection PROJ cannot name, in feet (autzen_trim)
  user_defined.linear_units_epsg = 9002;
  CHECK(axis_units(user_defined).horizontal == doctest::Approx(kFoot).epsilon(1e-12));

  CHECK(axis_units(Crs{}).metric());  // unknown: the file's own coordinates, taken as metres
  CHECK(axis_units(Crs{}).notes.empty());
  const Crs unread = resolved(epsg(999999));
  CHECK(unread.units.metric());
  CHECK_FALSE(unread.known());        // PROJ does not read it: the file's own coordinates
  REQUIRE(!unread.warnings.empty());  // and says it could not read it
  CHECK(contains(unread.warnings.back(), "PROJ does not read"));
}

TEST_CASE("crs units: the real samples' units from their headers") {
  if (!std::filesystem::is_directory(kLas) || !std::filesystem::is_directory(kLaz)) {
    MESSAGE("samples not found beside the clone: skipped");
    return;
  }
  const AxisUnits crop = axis_units(read_cloud_header(kLas + "/4_6_crop.las").crs);  // EPSG 2903 + 5103
  CHECK(crop.horizontal == doctest::Approx(kUsFoot).epsilon(1e-12));
  CHECK(crop.vertical == doctest::Approx(kUsFoot).epsilon(1e-12));
  const AxisUnits wkt = axis_units(read_cloud_header(kLas + "/test1_4.las").crs);  // WKT, ftUS
  CHECK(wkt.horizontal == doctest::Approx(kUsFoot).epsilon(1e-12));
  const AxisUnits autzen = axis_units(read_cloud_header(kLaz + "/twins/autzen_trim.laz").crs);
  CHECK(autzen.horizontal == doctest::Approx(kFoot).epsilon(1e-12));
  CHECK(axis_units(read_cloud_header(kLas + "/hexbin-crop.las").crs).metric());  // UTM 42N
}

TEST_CASE("crs units: a source in feet reads as metres, header bounds included") {
  VectorSource feet({1000.0, 2000.0, 100.0, 1010.0, 2020.0, 110.0});
  AxisUnits u;
  u.horizontal = u.vertical = kUsFoot;
  MetricSource metres(feet, u);
  double xyz[6];
  REQUIRE(metres.read(xyz, 2) == 2);
  CHECK(xyz[0] == doctest::Approx(1000.0 * kUsFoot));
  CHECK(xyz[5] == doctest::Approx(110.0 * kUsFoot));
  scale_to_file_units(u, xyz + 3);
  CHECK(xyz[3] == doctest::Approx(1010.0));
  CHECK(xyz[4] == doctest::Approx(2020.0));
}

TEST_CASE("crs units: a tile in US survey feet gives the metre tile's vehicles, centred in feet") {
  TempDir dir("crs-units");
  const FleetScene tile = fleet_scene(dir, 6, "--size 40 --vehicles 5 --trees 2 --seed 5");
  pipeline::DatabaseFile db;
  std::string error;
  REQUIRE_MESSAGE(pipeline::load_database(tile.db, &db, &error), error);
  std::vector<double> metres;
  REQUIRE_MESSAGE(spinhash::host::test::try_read_cloud(tile.scene, &metres, &error), error);
  std::vector<double> feet = metres;
  for (double& v : feet) v /= kUsFoot;
  AxisUnits ftus;
  ftus.horizontal = ftus.vertical = kUsFoot;

  const std::vector<Found> m = objects_of(db.db, metres, AxisUnits{});
  const std::vector<Found> f = objects_of(db.db, feet, ftus);
  const std::vector<Found> wrong = objects_of(db.db, feet, AxisUnits{});  // feet taken as metres
  const auto vehicles = [](const std::vector<Found>& v) {
    return std::count_if(v.begin(), v.end(), [](const Found& o) { return o.kind == "vehicle"; });
  };
  CHECK(vehicles(m) >= 4);
  // 3.28 times too large, the vehicles fail the size gates: few are vehicles
  // where they stand (in the feet numbers taken as metres).
  const auto still_a_vehicle = [&](const Found& v) {
    return std::any_of(wrong.begin(), wrong.end(), [&](const Found& o) {
      return o.kind == "vehicle" &&
             std::hypot(o.center[0] - v.center[0] / kUsFoot, o.center[1] - v.center[1] / kUsFoot) < 2.0;
    });
  };
  CHECK(std::count_if(m.begin(), m.end(), [&](const Found& v) {
          return v.kind == "vehicle" && still_a_vehicle(v);
        }) < vehicles(m));
  CHECK(std::none_of(wrong.begin(), wrong.end(), [](const Found& o) { return o.confident; }));
  REQUIRE(f.size() == m.size());
  for (size_t k = 0; k < m.size(); ++k) {
    CAPTURE(k);
    CHECK(f[k].kind == m[k].kind);
    CHECK(f[k].model == m[k].model);
    for (int a = 0; a < 3; ++a) {
      CHECK(f[k].center[a] * kUsFoot == doctest::Approx(m[k].center[a]).epsilon(1e-6));
      CHECK(f[k].translation[a] * kUsFoot == doctest::Approx(m[k].translation[a]).epsilon(1e-6));
    }
  }
}

TEST_CASE("crs units: a recognition's poses go back to the file's units, their rotations untouched") {
  RankedModel ranked[2] = {};
  ranked[0].pose.translation[0] = 1000.0 * kUsFoot;
  ranked[0].pose.translation[2] = 30.0;  // z in metres (a vertical CRS in metres)
  ranked[0].pose.rotation[0] = 1.0f;
  ranked[1].pose.translation[1] = 2000.0 * kUsFoot;
  Result r;
  r.ranking = ranked;
  r.ranking_count = 2;
  AxisUnits u;
  u.horizontal = kUsFoot;
  std::vector<RankedModel> copy;
  const Result f = pipeline::in_file_units(r, u, &copy);
  REQUIRE(f.ranking_count == 2);
  CHECK(f.ranking[0].pose.translation[0] == doctest::Approx(1000.0));
  CHECK(f.ranking[0].pose.translation[2] == 30.0);
  CHECK(f.ranking[0].pose.rotation[0] == 1.0f);
  CHECK(f.ranking[1].pose.translation[1] == doctest::Approx(2000.0));
  CHECK(ranked[0].pose.translation[0] == 1000.0 * kUsFoot);  // the workspace's ranking is left as it was
  CHECK(pipeline::in_file_units(r, AxisUnits{}, &copy).ranking == ranked);  // metres: nothing copied
}
