// One window of a scene: the stages every window of the stream runs (the
// tile API runs the stream): terrain, objects, size gates, the ownership
// rule, then recognition of each owned vehicle candidate, reported to a
// sink. The window's points are gathered (gather_window) from the stream's
// buffer.
#pragma once
#include <cstdint>

#include "geometry/terrain.hpp"
#include "scene/point_ring.hpp"
#include "scene/segment.hpp"
#include "scene/terrain_cells.hpp"
#include "scene/window_lattice.hpp"
#include "spinhash/scene_ownership.hpp"
#include "spinhash/scene_stream.hpp"

namespace spinhash {

struct WindowJob {
  OwnedArea core;   // objects whose centre lies here are this window's (stream frame: s, t)
  double s0 = 0.0;  // the window-local frame's origin in the stream frame
  double t0 = 0.0;
  int64_t row = 0;
  uint32_t col = 0;
};

// One window's working set, carved from the workspace.
struct WindowBuffers {
  Recognizer recognizer;
  uint32_t capacity = 0;
  float* local = nullptr;      // 3 x capacity: (s - s0, t - t0, z) per point
  uint32_t* source = nullptr;  // capacity: the point's index in the buffer
  float* height = nullptr;     // above the terrain
  uint8_t* ground = nullptr;
  uint32_t* label = nullptr;
  float* gathered = nullptr;    // 3 x capacity: object points, world-aligned
  uint32_t* offsets = nullptr;  // max_objects + 1
  double* box = nullptr;        // 4 x max_objects: exact s, t bounds per object
  ObjectShape* shapes = nullptr;
  RankedModel* ranking = nullptr;  // top_n: the object being reported
  TerrainParts terrain;
  SegmentGrid segments;

  // Carves the buffers (counting when the arena does), the recognizer's
  // workspace included; init_recognizer() then opens it.
  void carve(Arena& arena, const SceneConfig& c);
  Status init_recognizer(const Database* db, const SceneConfig& c);

 private:
  void* recognizer_workspace_ = nullptr;
  size_t recognizer_bytes_ = 0;
};

// Where a window's reports and counts go.
struct WindowOutput {
  SceneObjectSink sink = nullptr;
  void* context = nullptr;
  SceneStats* scene = nullptr;  // summed
  uint64_t* objects_reported = nullptr;
  uint64_t* objects_not_owned = nullptr;
};

RecognizerConfig scene_object_config(const SceneConfig& c);
TerrainParams scene_terrain_params(const SceneConfig& c);
SegmentParams scene_segment_params(const SceneConfig& c);

// Consecutive windows of one row share one terrain grid (a strip): as many
// columns as max_terrain_cells holds over their seen rectangles, at least
// one. Each point is then classified once per row, not once per window.
uint32_t strip_columns(const SceneConfig& c);

// The seen rectangle of the strip of columns [j0, j1) of row k, and the
// rectangle its windows gather.
FrameRect strip_rect(const WindowLattice& lattice, int64_t k, uint32_t j0, uint32_t j1);
FrameRect strip_gather_rect(const WindowLattice& lattice, int64_t k, uint32_t j0, uint32_t j1);

// Builds b.terrain from the stream's summed cells in `seen` (the strip's
// cells must be summed), in the local frame at (s0, t0) that the strip's
// windows then use (their WindowJob's s0, t0): the parts that reach into
// `gathered` (what the strip's windows gather), grown by the object margin
// (the terrain under a model's pose). kOk, kEmptyCloud (no point there),
// kTileTooLarge (their footprint needs more cells than carved). Counts the
// grid's cells and PMF windows into *st.
Status build_strip_terrain(const SceneConfig& c, const TerrainCells& cells, const FrameRect& seen,
                           const FrameRect& gathered, double s0, double t0, WindowBuffers& b, SceneStats* st);

// Gathers the buffer's points within `seen` into the window's local buffer,
// in the job's local frame; returns how many it holds, *missed how many did
// not fit (the window is then lost: kWindowOverflow).
uint32_t gather_window(const PointRing& ring, const FrameRect& seen, const WindowJob& job, WindowBuffers& b,
                       uint32_t* missed);

// Runs the stages on the window's n points, over the terrain its strip
// built (b.terrain, in the job's local frame), and reports the objects it
// owns. kOk, kTooManyObjects (objects past max_objects dropped, counted),
// kTileTooLarge (the window's footprint exceeds the grids: nothing reported).
Status run_window(const Database& db, const SceneConfig& c, const StreamFrame& frame, const PointRing& ring,
                  const WindowJob& job, uint32_t n, WindowBuffers& b, const WindowOutput& out);

}  // namespace spinhash
