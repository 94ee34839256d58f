// SceneRecognizer: the tile API, the stream's path over a tile held in
// memory. The tile is planned as every host front end plans a file
// (scene_tile.hpp): bands across, each a line of the stream, its rows along
// x pushed in order. The points stay where the caller keeps them, in any
// order: each row is one pass over them that pushes the row's points and
// finds the next row that holds any, so the passes follow the points.
#include "spinhash/scene.hpp"

#include <cmath>
#include <new>

#include "scene/scene_status.hpp"
#include "scene/window_lattice.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/scene_tile.hpp"

namespace spinhash {

namespace {

constexpr uint32_t kStagedPoints = 256;  // points pushed at once

}  // namespace

struct SceneBuffers {
  SceneStream stream;
  StreamConfig config;  // every band's
  void* stream_workspace = nullptr;
  size_t stream_bytes = 0;
  double* staged = nullptr;         // 3 x kStagedPoints
  SceneObject* objects = nullptr;   // max_objects: the tile's answers
  RankedModel* rankings = nullptr;  // max_objects x top_n
  uint32_t count = 0;
  uint32_t top_n = 0;
  uint32_t max_objects = 0;
  uint32_t dropped = 0;
};

namespace {

Status carve(Arena& arena, const SceneConfig& c, SceneBuffers& b) {
  b.stream_bytes = required_stream_workspace_bytes(tile_stream_config(c, 0));
  uint8_t* raw = arena.alloc<uint8_t>(b.stream_bytes + kBufferAlignment);
  b.stream_workspace = nullptr;
  if (raw != nullptr) {
    const uintptr_t at =
        (reinterpret_cast<uintptr_t>(raw) + kBufferAlignment - 1u) / kBufferAlignment * kBufferAlignment;
    b.stream_workspace = reinterpret_cast<void*>(at);
  }
  b.staged = arena.alloc<double>(3u * kStagedPoints);
  b.objects = arena.alloc<SceneObject>(c.max_objects);
  b.rankings = arena.alloc<RankedModel>(static_cast<size_t>(c.max_objects) * c.top_n);
  b.top_n = c.top_n;
  b.max_objects = c.max_objects;
  return arena.overflowed() || b.stream_bytes == 0 ? Status::kWorkspaceTooSmall : Status::kOk;
}

// The sink of the tile API: each reported object copied into the result.
void collect(void* context, const SceneObject& object, int64_t, uint32_t) {
  SceneBuffers& b = *static_cast<SceneBuffers*>(context);
  if (b.count >= b.max_objects) {
    ++b.dropped;
    return;
  }
  SceneObject& out = b.objects[b.count];
  out = object;
  if (object.ranking_count > 0) {
    RankedModel* dst = b.rankings + static_cast<size_t>(b.count) * b.top_n;
    for (uint32_t j = 0; j < object.ranking_count; ++j) dst[j] = object.ranking[j];
    out.ranking = dst;
  }
  ++b.count;
}

// The finite points' min and max corners (x y z) and their count.
uint32_t finite_bounds(const double* xyz, uint32_t n, double* lo, double* hi) {
  for (int a = 0; a < 3; ++a) {
    lo[a] = kUnbounded;
    hi[a] = -kUnbounded;
  }
  uint32_t m = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const double* p = xyz + 3u * i;
    if (!finite_xyz(p)) continue;
    for (int a = 0; a < 3; ++a) {
      lo[a] = p[a] < lo[a] ? p[a] : lo[a];
      hi[a] = p[a] > hi[a] ? p[a] : hi[a];
    }
    ++m;
  }
  return m;
}

struct Tile {
  const double* xyz;
  uint32_t n;
  const TilePlan* plan;
};

// Whether the band whose frame starts at origin_y takes the point: its t
// across, as the stream computes it, within the swath.
bool in_swath(const double* p, double origin_y, double t0, double t1) {
  const double t = p[1] - origin_y;
  return finite_xyz(p) && t >= t0 && t < t1;
}

// One band: its points (those its swath [t0, t1) takes) row by row; each
// pass pushes a row and finds the next row that holds any of them.
Status run_band(const Tile& t, uint32_t band, double t0, double t1, SceneBuffers& b) {
  double origin[3];
  tile_band_origin(*t.plan, band, origin);
  b.stream.reset(origin);
  const double y = origin[1];
  constexpr int64_t kNoRow = INT64_MAX;
  int64_t row = kNoRow;
  for (uint32_t i = 0; i < t.n; ++i) {
    const double* p = t.xyz + 3u * i;
    if (in_swath(p, y, t0, t1)) {
      const int64_t r = tile_row(*t.plan, p[0]);
      row = r < row ? r : row;
    }
  }
  Status status = Status::kOk;
  while (row != kNoRow) {
    int64_t next = kNoRow;
    uint32_t staged = 0;
    for (uint32_t i = 0; i < t.n; ++i) {
      const double* p = t.xyz + 3u * i;
      if (!in_swath(p, y, t0, t1)) continue;
      const int64_t r = tile_row(*t.plan, p[0]);
      if (r > row) {
        next = r < next ? r : next;
        continue;
      }
      if (r != row) continue;  // an earlier row's, pushed already
      for (int a = 0; a < 3; ++a) b.staged[3u * staged + a] = p[a];
      if (++staged == kStagedPoints) {
        status = worse_scene_status(status, b.stream.push(b.staged, staged));
        staged = 0;
      }
    }
    if (staged > 0) status = worse_scene_status(status, b.stream.push(b.staged, staged));
    row = next;
  }
  return worse_scene_status(status, b.stream.flush());
}

}  // namespace

const char* object_kind_name(ObjectKind k) noexcept {
  switch (k) {
    case ObjectKind::kVehicleCandidate: return "vehicle";
    case ObjectKind::kTooSmall: return "too small";
    case ObjectKind::kTooLarge: return "too large";
    case ObjectKind::kNotVehicleShaped: return "not vehicle-shaped";
    case ObjectKind::kUnknown: return "unknown";
  }
  return "unknown";
}

size_t required_scene_workspace_bytes(const SceneConfig& config) noexcept {
  if (!scene_config_valid(config) || !stream_config_valid(tile_stream_config(config, 0))) return 0;
  Arena counter;
  counter.alloc<SceneBuffers>(1);
  SceneBuffers scratch;
  carve(counter, config, scratch);
  return counter.used() + kBufferAlignment;
}

Status SceneRecognizer::init(const Database* db, const SceneConfig& config, void* workspace,
                             size_t workspace_bytes) noexcept {
  buffers_ = nullptr;
  db_ = nullptr;
  if (db == nullptr || !db->is_open() || workspace == nullptr || required_scene_workspace_bytes(config) == 0)
    return Status::kInvalidArgument;
  if (reinterpret_cast<uintptr_t>(workspace) % kBufferAlignment != 0) return Status::kMisalignedBuffer;
  Arena arena(workspace, workspace_bytes);
  SceneBuffers* b = arena.alloc<SceneBuffers>(1);
  if (b == nullptr) return Status::kWorkspaceTooSmall;
  new (b) SceneBuffers();
  Status s = carve(arena, config, *b);
  if (s != Status::kOk) return s;
  b->config = tile_stream_config(config, 0);
  s = b->stream.init(db, b->config, b->stream_workspace, b->stream_bytes, collect, b);
  if (s != Status::kOk) return s;
  db_ = db;
  config_ = config;
  used_bytes_ = arena.used();
  buffers_ = b;
  return Status::kOk;
}

SceneResult SceneRecognizer::recognize(const double* xyz, uint32_t n) noexcept {
  SceneResult res;
  if (buffers_ == nullptr) return res;  // kNotOpen
  if (n > 0 && xyz == nullptr) {
    res.status = Status::kInvalidArgument;
    return res;
  }
  SceneBuffers& b = *buffers_;
  b.count = 0;
  b.dropped = 0;
  double lo[3], hi[3];
  const uint32_t m = finite_bounds(xyz, n, lo, hi);
  res.stats.points_nonfinite = n - m;
  res.stats.workspace_used = used_bytes_;
  if (m == 0) {
    res.status = Status::kEmptyCloud;
    res.stats.points_in = n;
    return res;
  }
  const TilePlan plan = plan_tile(config_, lo, hi);
  const Tile tile{xyz, n, &plan};
  const StreamConfig& band_config = b.config;
  StreamStats total;
  res.status = Status::kOk;
  // The bands whose gathers hold points: each found by the least y beyond
  // the last band run.
  const double om = plan.object_margin;
  uint32_t band = tile_band_gathering(plan, lo[1]);
  while (band < plan.bands) {
    const Status s = run_band(tile, band, static_cast<double>(band_config.swath_min),
                              static_cast<double>(band_config.swath_max), b);
    add_stream_stats(total, b.stream.stats());
    res.status = worse_scene_status(res.status, s);
    double origin[3];
    tile_band_origin(plan, band, origin);
    const double next_from = origin[1] + plan.band_width - om;  // the next band's gather
    double least = kUnbounded;
    for (uint32_t i = 0; i < n; ++i) {
      const double* p = xyz + 3u * i;
      if (finite_xyz(p) && p[1] >= next_from && p[1] < least) least = p[1];
    }
    const uint32_t next = least < kUnbounded ? tile_band_gathering(plan, least) : plan.bands;
    band = next > band ? next : band + 1u;
  }
  res.stats = total.scene;
  res.stats.points_nonfinite = n - m;
  res.stats.workspace_used = used_bytes_;
  res.points_lost = total.points_outside + total.points_late + total.points_glitch + total.points_overflow;
  res.stats.objects_dropped += b.dropped;
  if (b.dropped > 0 && res.status == Status::kOk) res.status = Status::kTooManyObjects;
  res.objects = b.objects;
  res.object_count = b.count;
  return res;
}

}  // namespace spinhash
