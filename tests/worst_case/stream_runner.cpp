// Work per input point of the scene stream (scripts/instructions-per-point.sh):
//   stream_runner prepare DIR [SIDE_M [SPACING_M [LENGTH_M]]]  writes
//                 DIR/toy.shdb (the toy database), DIR/strip.f64 (raw native
//                 float64 xyz, scan order): a strip SIDE m across (default
//                 100) and LENGTH m along track (default SIDE) of sloped
//                 terrain at SPACING m (default 0.1) with toy vehicles, one
//                 per 300 m2 of ground, and DIR/truth.f64 (x y model per
//                 vehicle)
//   stream_runner run DIR [PRESET [WINDOW_MAX_WORK]]  pushes the strip
//                 through SceneStream in 4 kB chunks and flushes, between
//                 spinhash_bench_begin() and spinhash_bench_end(); prints
//                 points, objects, vehicles found and named right first, and
//                 stats; writes DIR/rows.csv: per row of windows along track,
//                 its input points, objects and recognition work units (what
//                 scripts/flight-keepup.py simulates a flight line from)
// Counted by callgrind on the host and by scripts/qemu/insn_count.c under
// qemu-user. The link wraps the three stages (-Wl,--wrap, tests/CMakeLists.txt)
// so that each call runs between markers of its own: the plugin counts a
// stage's instructions where callgrind gives its inclusive count.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_writer.hpp"
#include "blob/file_io.hpp"
#include "db/database_builder.hpp"
#include "geometry/terrain.hpp"
#include "scene/scene_window.hpp"
#include "scene/segment.hpp"
#include "spinhash/presets.hpp"
#include "spinhash/scene_stream.hpp"
#include "support/scene_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

// Markers: distinct bodies, so that no pass folds two of them into one address.
namespace {
volatile int bench_mark;
}
#define SPINHASH_MARKER(name, value) \
  extern "C" __attribute__((noinline)) void name() { bench_mark = value; }
SPINHASH_MARKER(spinhash_bench_begin, 1)
SPINHASH_MARKER(spinhash_bench_end, 2)
SPINHASH_MARKER(spinhash_bench_terrain_begin, 3)
SPINHASH_MARKER(spinhash_bench_terrain_end, 4)
SPINHASH_MARKER(spinhash_bench_segmentation_begin, 5)
SPINHASH_MARKER(spinhash_bench_segmentation_end, 6)
SPINHASH_MARKER(spinhash_bench_recognition_begin, 7)
SPINHASH_MARKER(spinhash_bench_recognition_end, 8)

// The wrapped stages (ld --wrap=SYMBOL sends the core's calls of SYMBOL to
// __wrap_SYMBOL; __real_SYMBOL is the original). Itanium-mangled names: the
// same on every Linux target.
// Terrain is three calls: each row's cell sums, each strip's grid from
// them, then each window's heights on it.
#define SPINHASH_CELLS _ZN8spinhash12TerrainCells3sumERKNS_9PointRingEdd
#define SPINHASH_TERRAIN \
  _ZN8spinhash19build_strip_terrainERKNS_11SceneConfigERKNS_12TerrainCellsERKNS_9FrameRectES8_ddRNS_13WindowBuffersEPNS_10SceneStatsE
#define SPINHASH_HEIGHTS _ZN8spinhash15terrain_heightsERKNS_12TerrainPartsEPKfjfPfPh
#define SPINHASH_SEGMENT \
  _ZN8spinhash15segment_objectsEPKfS1_PKhjRKNS_13SegmentParamsERNS_11SegmentGridEPNS_11ObjectShapeEPjPNS_12SegmentStatsE
#define SPINHASH_RECOGNIZE _ZN8spinhash10Recognizer9recognizeEPKfjRKNS_13ObjectTerrainE
#define SPINHASH_JOIN(a, b) a##b
#define SPINHASH_WRAP(sym) SPINHASH_JOIN(__wrap_, sym)
#define SPINHASH_REAL(sym) SPINHASH_JOIN(__real_, sym)

extern "C" {
void SPINHASH_REAL(SPINHASH_CELLS)(TerrainCells* self, const PointRing& ring, double from_s, double to_s);
Status SPINHASH_REAL(SPINHASH_TERRAIN)(const SceneConfig& c, const TerrainCells& cells, const FrameRect& seen,
                                       const FrameRect& gathered, double s0, double t0, WindowBuffers& b,
                                       SceneStats* st);
uint32_t SPINHASH_REAL(SPINHASH_HEIGHTS)(const TerrainParts& grid, const float* xyz, uint32_t n,
                                         float ground_height, float* height, uint8_t* ground);
Status SPINHASH_REAL(SPINHASH_SEGMENT)(const float* xyz, const float* height, const uint8_t* ground,
                                       uint32_t n, const SegmentParams& params, SegmentGrid& grid,
                                       ObjectShape* objects, uint32_t* label, SegmentStats* stats);
Result SPINHASH_REAL(SPINHASH_RECOGNIZE)(Recognizer* self, const float* xyz, uint32_t count,
                                         const ObjectTerrain& terrain);

void SPINHASH_WRAP(SPINHASH_CELLS)(TerrainCells* self, const PointRing& ring, double from_s, double to_s) {
  spinhash_bench_terrain_begin();
  SPINHASH_REAL(SPINHASH_CELLS)(self, ring, from_s, to_s);
  spinhash_bench_terrain_end();
}

Status SPINHASH_WRAP(SPINHASH_TERRAIN)(const SceneConfig& c, const TerrainCells& cells, const FrameRect& seen,
                                       const FrameRect& gathered, double s0, double t0, WindowBuffers& b,
                                       SceneStats* st) {
  spinhash_bench_terrain_begin();
  const Status s = SPINHASH_REAL(SPINHASH_TERRAIN)(c, cells, seen, gathered, s0, t0, b, st);
  spinhash_bench_terrain_end();
  return s;
}

uint32_t SPINHASH_WRAP(SPINHASH_HEIGHTS)(const TerrainParts& grid, const float* xyz, uint32_t n,
                                         float ground_height, float* height, uint8_t* ground) {
  spinhash_bench_terrain_begin();
  const uint32_t on_ground = SPINHASH_REAL(SPINHASH_HEIGHTS)(grid, xyz, n, ground_height, height, ground);
  spinhash_bench_terrain_end();
  return on_ground;
}

Status SPINHASH_WRAP(SPINHASH_SEGMENT)(const float* xyz, const float* height, const uint8_t* ground,
                                       uint32_t n, const SegmentParams& params, SegmentGrid& grid,
                                       ObjectShape* objects, uint32_t* label, SegmentStats* stats) {
  spinhash_bench_segmentation_begin();
  const Status s =
      SPINHASH_REAL(SPINHASH_SEGMENT)(xyz, height, ground, n, params, grid, objects, label, stats);
  spinhash_bench_segmentation_end();
  return s;
}

Result SPINHASH_WRAP(SPINHASH_RECOGNIZE)(Recognizer* self, const float* xyz, uint32_t count,
                                         const ObjectTerrain& terrain) {
  spinhash_bench_recognition_begin();
  const Result r = SPINHASH_REAL(SPINHASH_RECOGNIZE)(self, xyz, count, terrain);
  spinhash_bench_recognition_end();
  return r;
}
}

namespace {

constexpr double kDefaultSide = 100.0;       // m
constexpr double kSpacing = 0.1;             // m between ground points
constexpr float kVehicleSpacing = 0.1f;      // m between vehicle surface points
constexpr double kGroundPerVehicle = 300.0;  // m2 of ground per vehicle: the budget's density
constexpr double kMinSeparation = 8.0;       // m between vehicle centres: none touch
constexpr double kEdgeClearance = 4.0;       // m: vehicles lie inside the strip
constexpr double kSlopeDeg = 4.0;
constexpr double kUnderside = 0.35;           // m: model points below are not seen from the air
constexpr uint32_t kChunkPoints = 4096 / 24;  // 4 kB of xyz doubles
constexpr uint32_t kBufferedPoints = 1u << 21;
constexpr uint32_t kMaxKept =
    4096;  // objects kept for the truth check (fixed: nothing allocated while counted)
constexpr double kFoundRadius = 1.5;  // m between a vehicle's centre and its object's
constexpr uint32_t kMaxRows = 4096;   // rows of windows along track in rows.csv

int fail(const std::string& what) {
  std::fprintf(stderr, "stream_runner: %s\n", what.c_str());
  return 1;
}

struct Lcg {  // deterministic, standard-library independent
  uint64_t state;
  double uniform() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0);
  }
};

// Vehicle centres and yaws, at least kMinSeparation apart.
std::vector<double> place_vehicles(double length, double side, uint32_t count) {
  Lcg rng{17};
  std::vector<double> placed;  // x y yaw
  const double along = length - 2.0 * kEdgeClearance, across = side - 2.0 * kEdgeClearance;
  while (placed.size() / 3 < count) {
    const double x = -0.5 * along + along * rng.uniform(), y = -0.5 * across + across * rng.uniform();
    const double yaw = 6.283185307179586 * rng.uniform();
    bool clear = true;
    for (size_t i = 0; i < placed.size(); i += 3)
      clear = clear && std::hypot(x - placed[i], y - placed[i + 1]) >= kMinSeparation;
    if (clear) placed.insert(placed.end(), {x, y, yaw});
  }
  return placed;
}

// The strip, sorted along track (x): scan order.
std::vector<double> strip(double length, double side, double spacing, std::vector<double>* truth) {
  test::TerrainShape t;
  t.slope_deg = kSlopeDeg;
  test::Tile tile;
  test::add_terrain_rect(tile, t, -0.5 * length, 0.5 * length, -0.5 * side, 0.5 * side, spacing, 0.02, 9);
  const auto vehicles = static_cast<uint32_t>(std::lround(length * side / kGroundPerVehicle));
  const std::vector<double> at = place_vehicles(length, side, vehicles);
  for (size_t i = 0; i < at.size(); i += 3) {
    const uint32_t model = static_cast<uint32_t>(i / 3 % test::kToyModels);
    test::add_model(tile, t, test::toy_vehicle_points(model, kVehicleSpacing), at[i], at[i + 1], at[i + 2],
                    kUnderside);
    truth->insert(truth->end(), {at[i], at[i + 1], static_cast<double>(model)});
  }
  test::remove_occluded_ground(tile);
  return test::in_scan_order(tile, 0);
}

// Raw native float64: written and read on little-endian machines alike.
bool write_doubles(const std::string& path, const std::vector<double>& v, std::string* error) {
  std::vector<uint8_t> bytes(v.size() * sizeof(double));
  std::memcpy(bytes.data(), v.data(), bytes.size());
  return host::write_file_atomically(path, bytes, error);
}

int prepare(const std::string& dir, double side, double spacing, double length) {
  test::ToyDatabase toy;
  if (!test::make_toy_database(&toy)) return fail("toy database");
  std::string error;
  if (!host::write_file_atomically(
          dir + "/toy.shdb", std::vector<uint8_t>(toy.bytes.data(), toy.bytes.data() + toy.bytes.size()),
          &error))
    return fail(error);
  std::vector<double> truth;
  const std::vector<double> xyz = strip(length, side, spacing, &truth);
  if (!write_doubles(dir + "/strip.f64", xyz, &error) || !write_doubles(dir + "/truth.f64", truth, &error))
    return fail(error);
  std::printf("strip: %.0f x %.0f m, %zu points, %zu vehicles\n", length, side, xyz.size() / 3,
              truth.size() / 3);
  return 0;
}

// The stream over the strip: rows along x on absolute multiples of the core
// (as tile_stream.cpp puts them), an owned band across that holds the whole
// strip, the default window stages.
constexpr float kOwnHalfWidth = 64.0f;  // m across either side of the origin: the 100 m strip

StreamConfig bench_config(const double* first, Preset preset, uint64_t window_max_work) {
  StreamConfig c;
  apply_preset(preset, &c.scene.recognizer);
  c.scene.window_max_work = window_max_work;
  const double core = c.scene.window_core;
  c.origin_given = true;
  c.origin[0] = std::floor(first[0] / core) * core;
  c.heading_deg = 0.0f;
  c.swath_min = c.own_min = -kOwnHalfWidth;
  c.swath_max = c.own_max = kOwnHalfWidth;
  c.max_lag = 4.0f;
  c.max_buffered_points = kBufferedPoints;
  return c;
}

struct Kept {
  double x, y;
  int64_t model;  // -1 without a ranking
};

struct Row {
  uint64_t points = 0, objects = 0, work = 0;
};

struct Tally {
  uint64_t by_kind[kObjectKinds] = {};
  uint64_t confident = 0;
  Kept kept[kMaxKept];
  uint32_t kept_count = 0;
  Row rows[kMaxRows];
};

void tally(void* context, const SceneObject& o, int64_t row, uint32_t) {
  Tally& t = *static_cast<Tally*>(context);
  if (row >= 0 && row < static_cast<int64_t>(kMaxRows)) {
    ++t.rows[row].objects;
    t.rows[row].work += o.stats.cascade.work;
  }
  ++t.by_kind[static_cast<uint32_t>(o.kind)];
  t.confident += o.confident ? 1u : 0u;
  if (t.kept_count < kMaxKept)
    t.kept[t.kept_count++] = Kept{o.center[0], o.center[1], o.ranking_count ? o.ranking[0].model : -1};
}

struct Score {
  uint32_t vehicles = 0, found = 0, right_first = 0, twice = 0;
};

// Each true vehicle against the objects whose centre lies within kFoundRadius.
Score score(const Tally& t, const host::AlignedBytes& truth) {
  Score s;
  const auto* v = reinterpret_cast<const double*>(truth.data());
  s.vehicles = static_cast<uint32_t>(truth.size() / (3 * sizeof(double)));
  for (uint32_t i = 0; i < s.vehicles; ++i) {
    uint32_t near = 0, right = 0;
    for (uint32_t k = 0; k < t.kept_count; ++k) {
      if (std::hypot(t.kept[k].x - v[3 * i], t.kept[k].y - v[3 * i + 1]) > kFoundRadius) continue;
      ++near;
      right += t.kept[k].model == static_cast<int64_t>(v[3 * i + 2]) ? 1u : 0u;
    }
    s.found += near > 0 ? 1u : 0u;
    s.right_first += right > 0 ? 1u : 0u;
    s.twice += near > 1 ? 1u : 0u;
  }
  return s;
}

// DIR/rows.csv: each row's input points (by x from the stream's origin, rows
// of window_core along track), objects and recognition work units.
bool write_rows(const std::string& dir, Tally& t, const double* xyz, uint32_t n, const StreamConfig& c,
                std::string* error) {
  uint32_t last = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const double k = std::floor((xyz[3u * i] - c.origin[0]) / c.scene.window_core);
    if (k < 0.0 || k >= kMaxRows) continue;
    ++t.rows[static_cast<uint32_t>(k)].points;
    last = static_cast<uint32_t>(k) > last ? static_cast<uint32_t>(k) : last;
  }
  std::string csv = "row,points,objects,recognition_work\n";
  for (uint32_t k = 0; k <= last; ++k)
    csv += std::to_string(k) + "," + std::to_string(t.rows[k].points) + "," +
           std::to_string(t.rows[k].objects) + "," + std::to_string(t.rows[k].work) + "\n";
  return host::write_file_atomically(dir + "/rows.csv", std::vector<uint8_t>(csv.begin(), csv.end()), error);
}

int run(const std::string& dir, Preset preset, uint64_t window_max_work) {
  host::AlignedBytes blob, cloud, truth;
  std::string error;
  if (!host::read_file(dir + "/toy.shdb", &blob, &error) ||
      !host::read_file(dir + "/strip.f64", &cloud, &error) ||
      !host::read_file(dir + "/truth.f64", &truth, &error))
    return fail(error + " (run prepare first)");
  Database db;
  if (Database::open(blob.data(), blob.size(), &db) != Status::kOk) return fail("database does not open");
  const auto* xyz = reinterpret_cast<const double*>(cloud.data());  // 64-byte aligned buffer
  const auto n = static_cast<uint32_t>(cloud.size() / (3 * sizeof(double)));
  if (n == 0) return fail("empty strip");
  const StreamConfig config = bench_config(xyz, preset, window_max_work);
  host::AlignedBytes workspace(required_stream_workspace_bytes(config));
  SceneStream stream;
  static Tally t;  // large: not on the stack
  if (stream.init(&db, config, workspace.data(), workspace.size(), tally, &t) != Status::kOk)
    return fail("init failed");
  Status status = Status::kOk;
  spinhash_bench_begin();
  for (uint32_t i = 0; i < n; i += kChunkPoints) {
    const Status s =
        stream.push(xyz + 3u * static_cast<size_t>(i), n - i < kChunkPoints ? n - i : kChunkPoints);
    status = s != Status::kOk ? s : status;
  }
  const Status f = stream.flush();
  spinhash_bench_end();
  const StreamStats& st = stream.stats();
  const Score sc = score(t, truth);
  std::printf(
      "points=%u vehicles=%u found=%u right_first=%u twice=%u objects=%llu vehicle_candidates=%llu "
      "confident=%llu too_small=%llu too_large=%llu not_vehicle_shaped=%llu unknown=%llu windows=%llu "
      "not_owned=%llu late=%llu overflow=%llu hypotheses=%llu workspace=%zu status=%s\n",
      n, sc.vehicles, sc.found, sc.right_first, sc.twice,
      static_cast<unsigned long long>(st.objects_reported), static_cast<unsigned long long>(t.by_kind[0]),
      static_cast<unsigned long long>(t.confident), static_cast<unsigned long long>(t.by_kind[1]),
      static_cast<unsigned long long>(t.by_kind[2]), static_cast<unsigned long long>(t.by_kind[3]),
      static_cast<unsigned long long>(t.by_kind[4]), static_cast<unsigned long long>(st.windows),
      static_cast<unsigned long long>(st.objects_not_owned), static_cast<unsigned long long>(st.points_late),
      static_cast<unsigned long long>(st.points_overflow),
      static_cast<unsigned long long>(st.scene.recognition_hypotheses), stream.used_bytes(),
      status_name(f != Status::kOk ? f : status));
  if (!write_rows(dir, t, xyz, n, config, &error)) return fail(error);
  return status == Status::kOk && f == Status::kOk ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 3 && argc <= 6 && std::strcmp(argv[1], "prepare") == 0) {
    const double side = argc >= 4 ? std::atof(argv[3]) : kDefaultSide;
    return prepare(argv[2], side, argc >= 5 ? std::atof(argv[4]) : kSpacing,
                   argc == 6 ? std::atof(argv[5]) : side);
  }
  Preset preset = Preset::kDefault;
  if (argc >= 3 && argc <= 5 && std::strcmp(argv[1], "run") == 0 &&
      (argc == 3 || preset_from_name(argv[3], &preset)))
    return run(argv[2], preset, argc == 5 ? std::strtoull(argv[4], nullptr, 10) : 0u);
  std::fprintf(stderr,
               "usage: stream_runner prepare DIR [SIDE_M [SPACING_M [LENGTH_M]]] | "
               "run DIR [default|flight|full [WINDOW_MAX_WORK]]\n");
  return 2;
}
