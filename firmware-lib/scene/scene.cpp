// SceneRecognizer: the tile API, a batch run of the stream's window stages
// (scene_window.hpp) over a tile held in memory. A tile that fits one window
// is one window with an unbounded core; a larger one is cut on the stream's
// lattice and each window gathers its points straight from the tile, so the
// order of the tile's points does not matter.
#include "spinhash/scene.hpp"

#include <cmath>
#include <limits>
#include <new>

#include "scene/scene_window.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {

struct SceneBuffers {
  WindowBuffers window;
  SceneObject* objects = nullptr;   // max_objects: the tile's answers
  RankedModel* rankings = nullptr;  // max_objects x top_n
  uint32_t count = 0;
  uint32_t top_n = 0;
  uint32_t max_objects = 0;
  uint32_t dropped = 0;
};

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

Status carve(Arena& arena, const SceneConfig& c, SceneBuffers& b) {
  b.window.carve(arena, c);
  b.objects = arena.alloc<SceneObject>(c.max_objects);
  b.rankings = arena.alloc<RankedModel>(static_cast<size_t>(c.max_objects) * c.top_n);
  b.top_n = c.top_n;
  b.max_objects = c.max_objects;
  return arena.overflowed() ? Status::kWorkspaceTooSmall : Status::kOk;
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

// Cells a grid of `cell` m needs over [0, ds] x [0, dt].
double grid_cells(double ds, double dt, float cell) {
  const double c = static_cast<double>(cell);
  return (ds / c + 2.0) * (dt / c + 2.0);
}

// One window (k, j) of a tile: its points gathered straight from the tile
// into the strip's local frame at (s0, t0), then the stages. A window whose
// points or terrain (`terrain`) did not fit is counted and lost.
struct TileWindows {
  const Database* db;
  const SceneConfig* c;
  const StreamFrame* frame;
  WindowSource src;
  uint32_t n;
  const WindowLattice* lattice;
  bool one_window;
};

Status run_tile_window(const TileWindows& t, Status terrain, int64_t k, uint32_t j, double s0, double t0,
                       WindowBuffers& w, const WindowOutput& out) {
  WindowJob job;
  job.row = k;
  job.col = j;
  job.core =
      t.one_window ? FrameRect{-kUnbounded, kUnbounded, -kUnbounded, kUnbounded} : t.lattice->core_rect(k, j);
  job.s0 = s0;
  job.t0 = t0;
  uint32_t missed = 0;
  const uint32_t got =
      gather_window(t.src, t.n, t.one_window ? job.core : t.lattice->gather_rect(k, j), job, w, &missed);
  if (got == 0) return Status::kOk;
  ++out.scene->windows;
  const Status s = missed > 0 || terrain != Status::kOk
                       ? Status::kWindowOverflow
                       : run_window(*t.db, *t.c, *t.frame, t.src, job, got, w, out);
  if (s != Status::kWindowOverflow && s != Status::kTileTooLarge) return s;
  ++out.scene->windows_overflowed;
  return Status::kWindowOverflow;
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
  if (!scene_config_valid(config)) return 0;
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
  if (db == nullptr || !db->is_open() || workspace == nullptr || !scene_config_valid(config))
    return Status::kInvalidArgument;
  if (reinterpret_cast<uintptr_t>(workspace) % kBufferAlignment != 0) return Status::kMisalignedBuffer;
  Arena arena(workspace, workspace_bytes);
  SceneBuffers* b = arena.alloc<SceneBuffers>(1);
  if (b == nullptr) return Status::kWorkspaceTooSmall;
  new (b) SceneBuffers();
  Status s = carve(arena, config, *b);
  if (s != Status::kOk) return s;
  s = b->window.init_recognizer(db, config);
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
  const SceneConfig& c = config_;
  b.count = 0;
  b.dropped = 0;
  // Heading +x; the origin on the absolute lattice of window cores below
  // the min corner, as `spinhash scene` streams a file: the same grid cells.
  StreamFrame frame;
  double hi[3];
  const uint32_t m = finite_bounds(xyz, n, frame.origin, hi);
  const double core = static_cast<double>(c.window_core);
  res.stats.points_nonfinite = n - m;
  res.stats.workspace_used = used_bytes_;
  if (m == 0) {
    res.status = Status::kEmptyCloud;
    res.stats.points_in = n;
    return res;
  }
  double extent[2];
  for (int a = 0; a < 2; ++a) {
    frame.origin[a] = std::floor(frame.origin[a] / core) * core;
    extent[a] = hi[a] - frame.origin[a];
  }
  const bool one_window = m <= c.max_tile_points &&
                          grid_cells(extent[0], extent[1], c.terrain_cell) <= c.max_terrain_cells &&
                          grid_cells(extent[0], extent[1], c.segment_cell) <= c.max_segment_cells;
  WindowLattice lattice;
  lattice.core = one_window ? kUnbounded : static_cast<double>(c.window_core);
  lattice.margin = static_cast<double>(c.window_margin);
  lattice.object_margin = static_cast<double>(c.object_margin);
  lattice.own_min = 0.0;
  lattice.own_max = one_window ? kUnbounded : (std::floor(extent[1] / core) + 1.0) * core;
  const int64_t rows = one_window ? 1 : lattice.row_of(extent[0]) + 1;
  const uint32_t cols = one_window ? 1u : lattice.columns();
  WindowSource src{xyz, nullptr, &frame};
  uint64_t reported = 0, not_owned = 0;
  const WindowOutput out{collect, &b, &res.stats, &reported, &not_owned};
  res.status = Status::kOk;
  const TileWindows tile{db_, &c, &frame, src, n, &lattice, one_window};
  const uint32_t per_strip = one_window ? 1u : strip_columns(c);
  for (int64_t k = 0; k < rows; ++k) {
    for (uint32_t j0 = 0; j0 < cols; j0 += per_strip) {
      const uint32_t j1 = j0 + per_strip < cols ? j0 + per_strip : cols;
      const FrameRect strip = one_window ? FrameRect{-kUnbounded, kUnbounded, -kUnbounded, kUnbounded}
                                         : strip_rect(lattice, k, j0, j1);
      const double s0 = one_window ? 0.0 : strip.s0, t0 = one_window ? 0.0 : strip.t0;
      const Status terrain = build_strip_terrain(c, src, n, strip, s0, t0, b.window, &res.stats);
      if (terrain == Status::kEmptyCloud) continue;
      for (uint32_t j = j0; j < j1; ++j) {
        const Status s = run_tile_window(tile, terrain, k, j, s0, t0, b.window, out);
        if (s == Status::kWindowOverflow) {
          res.status = Status::kWindowOverflow;
        } else if (s == Status::kTooManyObjects && res.status == Status::kOk) {
          res.status = s;
        } else if (s != Status::kOk && s != Status::kTooManyObjects) {
          res.status = s;
          return res;
        }
      }
    }
  }
  res.stats.points_in = n;
  res.stats.objects_dropped += b.dropped;
  if (b.dropped > 0 && res.status == Status::kOk) res.status = Status::kTooManyObjects;
  res.objects = b.objects;
  res.object_count = b.count;
  return res;
}

}  // namespace spinhash
