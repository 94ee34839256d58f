// scene-throughput: the scene path's throughput by stage, in points per
// second of one core (process CPU time of the calling thread), on a LAZ tile:
//   scene-throughput laz RAW.f64 OUT.laz       writes native float64 x y z
//                                               (stream_runner prepare's
//                                               strip) as a format-0 LAZ tile
//   scene-throughput sparse OUT.laz N SIDE     N points spread at random over
//                                               SIDE x SIDE m, as LAZ
//   scene-throughput sparse-tiles DIR T N SIDE T such tiles side by side (a
//                                               square of them), DIR/tNN.laz
//   scene-throughput decode TILE.laz           the tile's LAZ decoding alone
//   scene-throughput run DB.shdb TILE.laz...   per tile: the tile through
//                                               `spinhash scene`'s path
//                                               (pipeline/tile_stream.hpp),
//                                               decoded once, its time split
//                                               by stage
// The stages are timed by wrapping their calls at link time
// (experiments/CMakeLists.txt, -Wl,--wrap, as tests/worst_case/
// stream_runner.cpp counts their instructions): LAZ decoding (the reader's
// records, LasRecordReader::read, which also counts them), terrain (each
// row's cell sums, each strip's grid, each window's heights), segmentation,
// recognition, the along-track order (its spill and replay); the rest of
// the stream (the records' x y z, its buffer, the windows' gathering, the
// objects' boxes, ownership, gates) is the stream's time less the stages.
// Each row carries the records the reader decoded for its tile: the tile's
// records when it is decoded once. scripts/scene-throughput.sh makes the
// tiles and prints the table.
#include <time.h>

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cloud/las_header.hpp"
#include "cloud/laz/item_codec.hpp"
#include "cloud/point_source.hpp"
#include "laz_tile_writer.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/tile_stream.hpp"
#include "spinhash/recognizer.hpp"

using namespace spinhash;

namespace {

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

enum Stage { kDecoding, kTerrain, kSegmentation, kRecognition, kOrder, kStages };
double g_seconds[kStages] = {};
uint64_t g_records = 0;  // records the LAS/LAZ reader handed out

struct Timed {
  Stage stage;
  double start = thread_seconds();
  explicit Timed(Stage s) : stage(s) {}
  ~Timed() { g_seconds[stage] += thread_seconds() - start; }
};

}  // namespace

// The wrapped calls (ld --wrap=SYMBOL sends calls of SYMBOL across object
// files to __wrap_SYMBOL; __real_SYMBOL is the original).
#define SPINHASH_CELLS _ZN8spinhash12TerrainCells3sumERKNS_9PointRingEdd
#define SPINHASH_TERRAIN \
  _ZN8spinhash19build_strip_terrainERKNS_11SceneConfigERKNS_12TerrainCellsERKNS_9FrameRectES8_ddRNS_13WindowBuffersEPNS_10SceneStatsE
#define SPINHASH_HEIGHTS _ZN8spinhash15terrain_heightsERKNS_12TerrainPartsEPKfjfPfPh
#define SPINHASH_SEGMENT \
  _ZN8spinhash15segment_objectsEPKfS1_PKhjRKNS_13SegmentParamsERNS_11SegmentGridEPNS_11ObjectShapeEPjPNS_12SegmentStatsE
#define SPINHASH_RECOGNIZE _ZN8spinhash10Recognizer9recognizeEPKfjRKNS_13ObjectTerrainE
#define SPINHASH_ORDER_ADD _ZN8spinhash8pipeline15AlongTrackOrder3addEPKdm
#define SPINHASH_ORDER_READ _ZN8spinhash8pipeline15AlongTrackOrder6Cursor4readEPdm
#define SPINHASH_RECORDS _ZN8spinhash4host15LasRecordReader4readEPhm
#define SPINHASH_JOIN(a, b) a##b
#define SPINHASH_WRAP(sym) SPINHASH_JOIN(__wrap_, sym)
#define SPINHASH_REAL(sym) SPINHASH_JOIN(__real_, sym)

// The core's own types are opaque here (host code reaches the core through
// its public headers): references and pointers pass through unchanged.
extern "C" {
void SPINHASH_REAL(SPINHASH_CELLS)(void* self, const void* ring, double from_s, double to_s);
Status SPINHASH_REAL(SPINHASH_TERRAIN)(const SceneConfig& c, const void* cells, const void* seen,
                                       const void* gathered, double s0, double t0, void* b, SceneStats* st);
uint32_t SPINHASH_REAL(SPINHASH_HEIGHTS)(const void* parts, const float* xyz, uint32_t n, float ground_height,
                                         float* height, uint8_t* ground);
Status SPINHASH_REAL(SPINHASH_SEGMENT)(const float* xyz, const float* height, const uint8_t* ground,
                                       uint32_t n, const void* params, void* grid, void* objects,
                                       uint32_t* label, void* stats);
Result SPINHASH_REAL(SPINHASH_RECOGNIZE)(Recognizer* self, const float* xyz, uint32_t count,
                                         const ObjectTerrain& terrain);
void SPINHASH_REAL(SPINHASH_ORDER_ADD)(void* self, const double* xyz, size_t n);
size_t SPINHASH_REAL(SPINHASH_ORDER_READ)(void* self, double* xyz, size_t n);
size_t SPINHASH_REAL(SPINHASH_RECORDS)(void* self, uint8_t* out, size_t max);

void SPINHASH_WRAP(SPINHASH_CELLS)(void* self, const void* ring, double from_s, double to_s) {
  const Timed t(kTerrain);
  SPINHASH_REAL(SPINHASH_CELLS)(self, ring, from_s, to_s);
}
Status SPINHASH_WRAP(SPINHASH_TERRAIN)(const SceneConfig& c, const void* cells, const void* seen,
                                       const void* gathered, double s0, double t0, void* b, SceneStats* st) {
  const Timed t(kTerrain);
  return SPINHASH_REAL(SPINHASH_TERRAIN)(c, cells, seen, gathered, s0, t0, b, st);
}
uint32_t SPINHASH_WRAP(SPINHASH_HEIGHTS)(const void* parts, const float* xyz, uint32_t n, float ground_height,
                                         float* height, uint8_t* ground) {
  const Timed t(kTerrain);
  return SPINHASH_REAL(SPINHASH_HEIGHTS)(parts, xyz, n, ground_height, height, ground);
}
Status SPINHASH_WRAP(SPINHASH_SEGMENT)(const float* xyz, const float* height, const uint8_t* ground,
                                       uint32_t n, const void* params, void* grid, void* objects,
                                       uint32_t* label, void* stats) {
  const Timed t(kSegmentation);
  return SPINHASH_REAL(SPINHASH_SEGMENT)(xyz, height, ground, n, params, grid, objects, label, stats);
}
Result SPINHASH_WRAP(SPINHASH_RECOGNIZE)(Recognizer* self, const float* xyz, uint32_t count,
                                         const ObjectTerrain& terrain) {
  const Timed t(kRecognition);
  return SPINHASH_REAL(SPINHASH_RECOGNIZE)(self, xyz, count, terrain);
}
void SPINHASH_WRAP(SPINHASH_ORDER_ADD)(void* self, const double* xyz, size_t n) {
  const Timed t(kOrder);
  SPINHASH_REAL(SPINHASH_ORDER_ADD)(self, xyz, n);
}
size_t SPINHASH_WRAP(SPINHASH_ORDER_READ)(void* self, double* xyz, size_t n) {
  const Timed t(kOrder);
  return SPINHASH_REAL(SPINHASH_ORDER_READ)(self, xyz, n);
}
size_t SPINHASH_WRAP(SPINHASH_RECORDS)(void* self, uint8_t* out, size_t max) {
  const Timed t(kDecoding);
  const size_t got = SPINHASH_REAL(SPINHASH_RECORDS)(self, out, max);
  g_records += got;
  return got;
}
}

namespace {

constexpr double kLazScale = 0.001;  // m: LAS's usual 1 mm steps
constexpr uint32_t kLazChunk = 50000;
constexpr size_t kFormat0Bytes = 20;

// n points (x y z) as a format-0 LAZ tile at 1 mm steps.
bool write_laz(const std::string& path, const std::vector<double>& xyz, std::string* error) {
  host::LasHeader h;
  h.version_major = 1;
  h.version_minor = 2;
  h.point_count = xyz.size() / 3;
  for (int a = 0; a < 3; ++a) {
    h.min[a] = INFINITY;
    h.max[a] = -INFINITY;
  }
  for (size_t i = 0; i < xyz.size(); i += 3)
    for (int a = 0; a < 3; ++a) {
      h.min[a] = std::min(h.min[a], xyz[i + a]);
      h.max[a] = std::max(h.max[a], xyz[i + a]);
    }
  for (int a = 0; a < 3; ++a) {
    h.scale[a] = kLazScale;
    h.offset[a] = std::floor(h.min[a]);
  }
  std::vector<uint8_t> records(h.point_count * kFormat0Bytes, 0);
  for (size_t i = 0; i < h.point_count; ++i)
    for (int a = 0; a < 3; ++a)
      host::laz::put_i32(&records[i * kFormat0Bytes + 4 * a],
                         static_cast<int32_t>(std::llround((xyz[3 * i + a] - h.offset[a]) / kLazScale)));
  return experiment::write_format0_laz(path, h, records, kLazChunk, error);
}

int write_raw(const char* raw, const char* out) {
  std::ifstream in(raw, std::ios::binary);
  std::vector<double> xyz;
  double p[3];
  while (in.read(reinterpret_cast<char*>(p), sizeof p)) xyz.insert(xyz.end(), p, p + 3);
  std::string error;
  if (xyz.empty() || !write_laz(out, xyz, &error)) {
    std::fprintf(stderr, "scene-throughput: %s: %s\n", raw, xyz.empty() ? "no points" : error.c_str());
    return 1;
  }
  std::fprintf(stderr, "scene-throughput: %s: %zu points\n", out, xyz.size() / 3);
  return 0;
}

// n points spread at random over side x side m from (x0, y0), on a gentle slope.
std::vector<double> sparse_points(uint32_t n, double side, double x0, double y0, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, side);
  std::normal_distribution<double> noise(0.0, 2.0);
  std::vector<double> xyz;
  for (uint32_t i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng);
    xyz.insert(xyz.end(), {x0 + x, y0 + y, 100.0 + 0.01 * (x0 + x - 500000.0) + noise(rng)});
  }
  return xyz;
}

int write_sparse(const char* out, uint32_t n, double side) {
  std::string error;
  if (!write_laz(out, sparse_points(n, side, 500000.0, 4000000.0, 1), &error)) {
    std::fprintf(stderr, "scene-throughput: %s\n", error.c_str());
    return 1;
  }
  return 0;
}

int write_sparse_tiles(const std::string& dir, uint32_t tiles, uint32_t n, double side) {
  const auto across = static_cast<uint32_t>(std::ceil(std::sqrt(static_cast<double>(tiles))));
  for (uint32_t t = 0; t < tiles; ++t) {
    char name[32];
    std::snprintf(name, sizeof name, "/t%02u.laz", t);
    const double x0 = 500000.0 + side * (t % across), y0 = 4000000.0 + side * (t / across);
    std::string error;
    if (!write_laz(dir + name, sparse_points(n, side, x0, y0, t + 1), &error)) {
      std::fprintf(stderr, "scene-throughput: %s\n", error.c_str());
      return 1;
    }
  }
  return 0;
}

// The tile's points decoded alone: points and seconds.
double decode_seconds(const std::string& path, uint64_t* points) {
  const double t0 = thread_seconds();
  auto source = host::open_point_source(path);
  std::vector<double> xyz(3 * host::kDefaultChunkPoints);
  *points = 0;
  for (size_t n; (n = source->read(xyz.data(), host::kDefaultChunkPoints)) > 0;) *points += n;
  return thread_seconds() - t0;
}

void row(const char* tile, const char* stage, double seconds, uint64_t points, uint64_t records) {
  std::printf("%s,%s,%.4f,%.0f,%" PRIu64 "\n", tile, stage, seconds,
              seconds > 0.0 ? static_cast<double>(points) / seconds : 0.0, records);
}

int run(const char* db_path, int files, char** paths) {
  pipeline::DatabaseFile db;
  std::string error;
  if (!pipeline::load_database(db_path, &db, &error)) {
    std::fprintf(stderr, "scene-throughput: %s\n", error.c_str());
    return 1;
  }
  std::printf("tile,stage,cpu_s,points_per_s,records_decoded\n");
  for (int f = 0; f < files; ++f) {
    const std::string path = paths[f];
    for (double& s : g_seconds) s = 0.0;
    g_records = 0;
    pipeline::TileStreamOptions options;
    options.scene.max_tile_points = 0;                        // sized from the density, as `spinhash scene`
    options.scene.recognizer.ground.ground_clearance = 0.0f;  // the terrain takes the ground
    uint64_t objects = 0, vehicles = 0;
    const double t0 = thread_seconds();
    auto source = host::open_point_source(path);
    const pipeline::TileStreamResult r =
        pipeline::stream_tile(db.db, *source, options, [&](const SceneObject& o) {
          ++objects;
          vehicles += o.kind == ObjectKind::kVehicleCandidate ? 1u : 0u;
        });
    const double total = thread_seconds() - t0;
    double rest = total;
    for (const double s : g_seconds) rest -= s;
    const uint64_t points = r.points_read, records = g_records;
    const std::string name = std::filesystem::path(path).filename().string();
    std::fprintf(stderr,
                 "scene-throughput: %s: %s, %" PRIu64 " points (%" PRIu64 " records decoded), %" PRIu64
                 " objects (%" PRIu64 " vehicle candidates), %" PRIu64 " windows in %u bands\n",
                 name.c_str(), status_name(r.status), points, records, objects, vehicles, r.stats.windows,
                 r.bands);
    const char* n = name.c_str();
    row(n, "laz_decoding", g_seconds[kDecoding], points, records);
    row(n, "along_track_order", g_seconds[kOrder], points, records);
    row(n, "terrain", g_seconds[kTerrain], points, records);
    row(n, "segmentation", g_seconds[kSegmentation], points, records);
    row(n, "stream_rest", rest, points, records);
    row(n, "recognition", g_seconds[kRecognition], points, records);
    row(n, "all_but_recognition", total - g_seconds[kRecognition], points, records);
    row(n, "total", total, points, records);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 4 && std::strcmp(argv[1], "laz") == 0) return write_raw(argv[2], argv[3]);
    if (argc == 5 && std::strcmp(argv[1], "sparse") == 0)
      return write_sparse(argv[2], static_cast<uint32_t>(std::stoul(argv[3])), std::stod(argv[4]));
    if (argc == 6 && std::strcmp(argv[1], "sparse-tiles") == 0)
      return write_sparse_tiles(argv[2], static_cast<uint32_t>(std::stoul(argv[3])),
                                static_cast<uint32_t>(std::stoul(argv[4])), std::stod(argv[5]));
    if (argc >= 4 && std::strcmp(argv[1], "run") == 0) return run(argv[2], argc - 3, argv + 3);
    if (argc == 3 && std::strcmp(argv[1], "decode") == 0) {
      uint64_t points = 0;
      const double s = decode_seconds(argv[2], &points);
      std::printf("%" PRIu64 " points decoded in %.4f CPU s\n", points, s);
      return 0;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scene-throughput: %s\n", e.what());
    return 1;
  }
  std::fprintf(
      stderr,
      "usage: scene-throughput laz RAW.f64 OUT.laz | sparse OUT.laz N SIDE_M | sparse-tiles DIR T N SIDE_M "
      "| decode TILE.laz | run DB.shdb TILE.laz...\n");
  return 2;
}
