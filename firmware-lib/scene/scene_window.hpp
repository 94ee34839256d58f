// One window of a scene: the stages every scene path shares (the tile API
// and the stream): terrain, objects, size gates, the ownership rule, then
// recognition of each owned vehicle candidate, reported to a sink. The
// window's points are gathered (gather_window) from wherever the caller
// keeps them (the stream's buffer, a caller's tile), through a WindowSource.
#pragma once
#include <cstdint>

#include "geometry/terrain.hpp"
#include "scene/point_ring.hpp"
#include "scene/segment.hpp"
#include "scene/terrain_cells.hpp"
#include "scene/window_lattice.hpp"
#include "spinhash/scene_stream.hpp"

namespace spinhash {

// The stream-frame coordinates (on the 1 mm lattice) of a window point's
// source, by index: world xyz through the frame (a tile) or the stream's
// buffer.
struct WindowSource {
  const double* world = nullptr;  // 3 per point (a tile), or
  const PointRing* ring = nullptr;
  const StreamFrame* frame = nullptr;
  void stz(uint32_t i, double* out) const {
    if (world)
      frame->to_lattice(world + 3u * static_cast<size_t>(i), out);
    else
      ring->get(i, out);
  }
};

struct WindowJob {
  FrameRect core;   // objects whose centre lies here are this window's
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
  uint32_t* source = nullptr;  // capacity: the point's index in its WindowSource
  float* height = nullptr;     // above the terrain
  uint8_t* ground = nullptr;
  uint32_t* label = nullptr;
  float* gathered = nullptr;    // 3 x capacity: object points, world-aligned
  uint32_t* offsets = nullptr;  // max_objects + 1
  double* box = nullptr;        // 4 x max_objects: exact s, t bounds per object
  ObjectShape* shapes = nullptr;
  RankedModel* ranking = nullptr;  // top_n: the object being reported
  TerrainGrid terrain;
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

// Consecutive windows of one row share one terrain grid (a strip): as many
// columns as max_terrain_cells holds over their seen rectangles, at least
// one. Each point is then classified once per row, not once per window.
uint32_t strip_columns(const SceneConfig& c);

// The seen rectangle of the strip of columns [j0, j1) of row k.
FrameRect strip_rect(const WindowLattice& lattice, int64_t k, uint32_t j0, uint32_t j1);

// Builds b.terrain over the points of src (indices 0..n-1) that lie in
// `seen`, in the local frame at (s0, t0) that the strip's windows then use
// (their WindowJob's s0, t0). kOk, kEmptyCloud (no point in the strip),
// kTileTooLarge (their footprint needs more cells than carved). Counts the
// grid's cells and PMF windows into *st.
Status build_strip_terrain(const SceneConfig& c, const WindowSource& src, uint32_t n, const FrameRect& seen,
                           double s0, double t0, WindowBuffers& b, SceneStats* st);
// The same from the stream's summed cells (the strip's cells must be summed).
Status build_strip_terrain(const SceneConfig& c, const TerrainCells& cells, const FrameRect& seen, double s0,
                           double t0, WindowBuffers& b, SceneStats* st);

// Calls f(stz, i) with the stream-frame point of each of src's n points
// that lies in `seen`, in index order. The stream's buffer holds finite
// frame points already; a tile's world points may be anything (non-finite
// ones are skipped).
template <class F>
void for_points_in(const WindowSource& src, uint32_t n, const FrameRect& seen, F&& f) {
  for (uint32_t i = 0; i < n; ++i) {
    double stz[3];
    if (src.world && !finite_xyz(src.world + 3u * static_cast<size_t>(i))) continue;
    src.stz(i, stz);
    if (seen.holds(stz[0], stz[1])) f(stz, i);
  }
}

// Gathers the points of src within `seen` into the window's local buffer,
// in the job's local frame; returns how many it holds, *missed how many did
// not fit (the window is then lost: kWindowOverflow).
uint32_t gather_window(const WindowSource& src, uint32_t n, const FrameRect& seen, const WindowJob& job,
                       WindowBuffers& b, uint32_t* missed);

// Runs the stages on the window's n points, over the terrain its strip
// built (b.terrain, in the job's local frame), and reports the objects it
// owns. kOk, kTooManyObjects (objects past max_objects dropped, counted),
// kTileTooLarge (the window's footprint exceeds the grids: nothing reported).
Status run_window(const Database& db, const SceneConfig& c, const StreamFrame& frame, const WindowSource& src,
                  const WindowJob& job, uint32_t n, WindowBuffers& b, const WindowOutput& out);

}  // namespace spinhash
