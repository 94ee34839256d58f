// The stream's terrain cells: each buffered point's terrain sums (lowest
// and next lowest, then the low band: geometry/terrain.hpp) on the frame's
// fixed lattice of terrain_cell m, kept as long as a strip of windows still
// needs them.
// Summed once, when no point can still arrive in the cell (the row's
// lookahead), so the buffer keeps points only while a window gathers them
// (object_margin), not for the terrain filter's reach (window_margin).
// Along track the slots are a ring over the cell index; across they cover
// the owned band and its margins. Each slot row keeps the span of its
// occupied cells, so clearing, finding and filling cost what the points
// occupy, not the area they span.
#pragma once
#include <cstdint>

#include "geometry/terrain.hpp"
#include "scene/point_ring.hpp"
#include "scene/window_lattice.hpp"
#include "spinhash/arena.hpp"

namespace spinhash {

struct TerrainCells {
  float* lowest = nullptr;  // per slot, NaN: no point
  float* next = nullptr;    // per slot: the next lowest, NaN: at most one point
  float* band_sum = nullptr;
  float* band_count = nullptr;
  uint32_t* span = nullptr;        // per slot row: first occupied slot across, then last (first > last: none)
  uint32_t along = 0, across = 0;  // slots
  double cell = 0.5;
  float low_band = 0.3f;   // m: TerrainParams::low_band
  float noise_gap = 1.0f;  // m: TerrainParams::noise_gap (the band's base)
  double t_min = 0.0;      // across: where cell 0 starts
  int64_t summed_to = 0;   // cells along below this index are summed (the last `along` of them kept)
  bool started = false;
  bool cleared = false;  // every slot outside its row's span is empty (after the first start)

  // Slots for strips `depth` m deep over `width` m across.
  void carve(Arena& arena, double cell_m, double depth, double width);
  // Starts a line: every slot empty (the first time all of them, then the
  // rows' spans), cell 0 across at t_lo.
  void start(double t_lo);
  int64_t index_along(double s) const;
  // The along-track edge (m) below which every cell is summed.
  double summed_edge() const { return static_cast<double>(summed_to) * cell; }
  // Sums the ring's points in the cells from `from_s` (or where the last
  // sum ended, if later) up to `to_s` along (both on the lattice).
  void sum(const PointRing& ring, double from_s, double to_s);
  // Puts the cells of `rect` (on the lattice) that hold points into parts,
  // in the local frame at (s0, t0): cells closer than the filter's reach
  // (`reach_cells`: terrain_reach_cells) are in one part (blocks within
  // kTerrainBlocksPerReach of each other), on a grid over their footprint.
  // Only the parts that reach into `needed` are made: the others change no
  // height there. kOk, kEmptyCloud (no part), kTileTooLarge (the parts need
  // more cells than carved).
  Status fill(const FrameRect& rect, const FrameRect& needed, double s0, double t0, uint32_t reach_cells,
              TerrainParts& parts) const;

 private:
  uint32_t slot(int64_t i, uint32_t it) const;
  uint32_t* span_of(int64_t i) const;
  // Scratch of fill: per block the footprint of its cells (relative cell
  // indices: along min, max, across min, max) and its union-find parent;
  // per part its first cell.
  int32_t* block_box_ = nullptr;  // 4 x kMaxTerrainBlocks
  uint16_t* block_parent_ = nullptr;
  int32_t* part_first_ = nullptr;  // 2 x kMaxTerrainParts
};

}  // namespace spinhash
