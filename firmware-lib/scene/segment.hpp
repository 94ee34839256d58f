// Objects of a tile: connected components of the above-ground points on a
// fixed-capacity cell grid (union-find, no recursion), in two layers: the
// low one holds the points up to a height above the terrain that rise from
// the lowest point of their cell without an empty vertical gap of
// layer_gap_bins height bins; the rest (tree crowns, a crown's part over a
// car, roofs of tall buildings) is the high layer. Cars parked side by side
// part at the empty gap between them, and a crown over a car stays apart
// from it. The grid covers the footprint of the points above the ground:
// ground points join no object.
#pragma once
#include <cstdint>

#include "spinhash/arena.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/status.hpp"

namespace spinhash {

constexpr uint32_t kNoObject = 0xFFFFFFFFu;

struct SegmentParams {
  float cell = 0.25f;         // m
  float split_height = 3.8f;  // m above terrain: low layer at or below, high layer above
  uint32_t min_points = 30;   // smaller components are fragments
  uint32_t max_objects = 256;
  float column_bin = 0.25f;     // m: height bins of a cell's column (kSegmentColumnBins of them)
  uint32_t layer_gap_bins = 4;  // empty bins that part a column (< kSegmentColumnBins)
};

struct SegmentGrid {
  uint32_t max_cells = 0;
  uint32_t* parent = nullptr;  // 2 layers x max_cells: union-find forest (kNoObject: empty cell)
  uint32_t* object = nullptr;  // 2 layers x max_cells: per root, points, then object id
  uint32_t* column = nullptr;  // max_cells: occupied height bins, then the top of the low layer
  // The frame: the whole footprint's min corner snapped to the cell (the
  // origin of the objects' sums) and its size in cells; the grid is its
  // cells [ox, ox + nx) x [oy, oy + ny) that the points above ground span.
  float x0 = 0.0f, y0 = 0.0f, cell = 0.25f;
  uint32_t frame_nx = 0, frame_ny = 0;
  uint32_t ox = 0, oy = 0, nx = 0, ny = 0;

  void carve(Arena& arena, uint32_t cells);
};

// Per-object sums and bounds; the footprint's principal axes give length and width.
struct ObjectShape {
  uint32_t points = 0;
  bool high_layer = false;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;  // double: sums of up to 4M squares
  float zmin = 0, zmax = 0, hmin = 0, hmax = 0;      // z and height above terrain
  float ax = 1.0f, ay = 0.0f;                        // unit length axis
  float umin = 0, umax = 0, vmin = 0, vmax = 0;      // footprint along (ax, ay) and across
  float cx = 0, cy = 0;                              // footprint centre (local frame)
  float length() const { return umax - umin; }
  float width() const { return vmax - vmin; }
};

struct SegmentStats {
  uint32_t cells = 0;
  uint32_t components = 0;
  uint32_t objects = 0;
  uint32_t dropped = 0;  // objects past max_objects
};

// label[i] = object of point i (kNoObject: ground, fragment or dropped).
// kTileTooLarge when the footprint of the points above ground needs more
// than grid.max_cells cells,
// kTooManyObjects when objects were dropped past max_objects (the rest valid).
Status segment_objects(const float* xyz, const float* height, const uint8_t* ground, uint32_t n,
                       const SegmentParams& params, SegmentGrid& grid, ObjectShape* objects, uint32_t* label,
                       SegmentStats* stats);

}  // namespace spinhash
