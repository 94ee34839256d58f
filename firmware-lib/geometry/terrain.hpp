// Terrain classification for airborne clouds on sloped, uneven ground (not in
// the paper): a lowest-points grid filtered by a progressive morphological
// opening (Zhang et al. 2003, the PMF of PDAL), then each point's height
// above the local terrain surface. Opening preserves planes of any slope and
// steps (curbs), and removes anything narrower than the window; a cell is
// off the ground when the opening lowers it by more than the slope allowance
// of that window. Memory: a few floats per grid cell, carved by the caller.
//
// The scene's path (scene/terrain_cells.hpp): each cell's sums (its lowest
// z, then the points within low_band of it), the cells that hold points put
// into TerrainParts, the filter run on each part, then the points' heights.
// Parts are the groups of occupied cells that lie farther apart than the
// filter reaches (terrain_reach_cells): each is filtered on a grid over its
// own footprint, so the work follows the points, not the area they span.
#pragma once
#include <cmath>
#include <cstdint>

#include "spinhash/arena.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/status.hpp"

namespace spinhash {

struct TerrainParams {
  float cell = 0.5f;            // m: grid cell edge
  float max_window = 24.0f;     // m: largest opening window (wider than any building to remove)
  float slope = 0.35f;          // s of PMF: rise per m allowed between windows (0.35 ~ 19 degrees)
  float dh0 = 0.2f;             // m: dh_0, height tolerance of the smallest window
  float dh_max = 2.5f;          // m: dh_max, the cap of the height tolerance
  float ground_height = 0.25f;  // m: a point at most this far above the terrain is ground
  float low_band = 0.3f;        // m: a cell's value is the mean of its points this close to its lowest
  float noise_gap =
      1.0f;  // m (0: off): a cell's lowest this far under its next and its surroundings is noise
  float noise_reach = 1.0f;    // m: the surroundings of that test
  uint32_t noise_support = 2;  // cells around within the gap that keep a lowest (or a quarter, if fewer)
};

// One dense grid of cells (a part of a strip's terrain); its buffers come
// from an Arena, or from the TerrainParts that holds it.
struct TerrainGrid {
  uint32_t max_cells = 0;
  float* value = nullptr;    // per cell: low mean z (NaN: no point); its lowest z until terrain_finish
  float* surface = nullptr;  // per cell: terrain z (NaN: no data within the largest window); its next
                             // lowest z until terrain_finish
  float* scratch = nullptr;  // per cell: opening buffers
  float* opened = nullptr;
  float* line = nullptr;          // one row or column: the opening's running extremes
  uint8_t* off_ground = nullptr;  // per cell: 1 when the filter flagged it (first: its lowest is low noise)
  uint32_t nx = 0, ny = 0;
  float x0 = 0.0f, y0 = 0.0f;  // min corner of cell (0, 0)
  float cell = 0.5f;

  // Carves the buffers for `max_cells` cells (counting when the arena does).
  void carve(Arena& arena, uint32_t cells);
};

// The terrain of a strip: up to kMaxTerrainParts grids in one carved
// buffer, and the blocks (squares of `block` m) that say which part covers
// a point. Cells of different parts lie farther apart than the filter
// reaches, so each part's surface is the one its own cells give.
struct TerrainParts {
  TerrainGrid whole;            // the carved buffers
  TerrainGrid* part = nullptr;  // kMaxTerrainParts, carved
  uint32_t count = 0;
  uint32_t cells = 0;  // cells used by the parts, together
  float cell = 0.5f;
  float x0 = 0.0f, y0 = 0.0f;     // min corner of block (0, 0): a multiple of `cell`
  float block = 0.0f;             // m: block edge
  uint32_t bx = 0, by = 0;        // blocks
  uint8_t* block_part = nullptr;  // kMaxTerrainBlocks, carved: per block its part, kNoTerrainPart: none

  void carve(Arena& arena, uint32_t max_cells);
  // The part that covers (x, y) (local frame), nullptr: none.
  const TerrainGrid* part_at(float x, float y) const;
};
constexpr uint8_t kNoTerrainPart = 0xFFu;

// Passes of the low-noise test: a pit beside a deeper one is judged in the
// second, once the deeper one is out.
constexpr uint32_t kTerrainNoisePasses = 2;
// Cells each way that the low-noise test compares a cell with (0: off).
uint32_t terrain_noise_reach_cells(const TerrainParams& params);
// Cells within which the filter's result at a cell depends on others: the
// openings' reach (each window erodes and dilates by its half-width) or
// the gap fill's, whichever is larger, after the low-noise test's passes.
uint32_t terrain_reach_cells(const TerrainParams& params);

// Begins the parts over a rectangle of bx x by blocks of `block_cells`
// cells from (x0, y0) (local frame, a multiple of `cell`): no part yet.
// false when more blocks than kMaxTerrainBlocks.
bool terrain_parts_begin(TerrainParts& parts, float cell, float x0, float y0, uint32_t block_cells,
                         uint32_t bx, uint32_t by);
// Adds a part of nx x ny cells from (x0, y0) covering the blocks whose
// block_part the caller sets to the index returned; kNoTerrainPart when no
// room (cells or parts). Its cells start empty (put each with terrain_put_cell).
uint8_t terrain_add_part(TerrainParts& parts, float x0, float y0, uint32_t nx, uint32_t ny);
// A cell's sums (terrain_lowest, terrain_low_band): its lowest z, its next
// lowest (NaN: one point) and its low band.
void terrain_put_cell(TerrainGrid& grid, uint32_t ix, uint32_t iy, float lowest, float next, float band_sum,
                      float band_count);
// Filters every part: low noise left out of each cell's value, the
// progressive filter, the gaps filled. Returns the PMF windows run (per
// part: the same); `noise_cells` (if given) adds the cells whose lowest
// was low noise.
uint32_t terrain_finish(TerrainParts& parts, const TerrainParams& params, uint32_t* noise_cells = nullptr);
// height[i] = z - terrain at each of the n points (local frame, within the
// parts' blocks); ground[i] = 1 within ground_height. Returns the ground points.
uint32_t terrain_heights(const TerrainParts& parts, const float* xyz, uint32_t n, float ground_height,
                         float* height, uint8_t* ground);

// Terrain z at (x, y): bilinear over the cell centres around it, skipping
// cells without data (the point's own cell always has some). NaN outside
// every part.
float terrain_height_at(const TerrainParts& parts, float x, float y);
float terrain_height_at(const TerrainGrid& grid, float x, float y);

bool terrain_params_valid(const TerrainParams& p);

// A cell's sums, point by point: its lowest z and its next lowest (NaN:
// none yet), then, once those are final, the points within `band` above
// the band's base (relative to it: small sums, no float drift). The base is
// the lowest, or the next where the lowest may be low noise (then the
// lowest stands alone, since noise_gap is at least the band): the cell's
// value is the base + sum / count, or the lowest alone when kept.
inline void terrain_lowest(float& lowest, float& next, float z) {
  if (std::isnan(lowest) || z < lowest) {
    next = lowest;
    lowest = z;
  } else if (std::isnan(next) || z < next) {
    next = z;
  }
}
// Whether a cell's lowest may be low noise: noise_gap under its next (or
// alone in its cell). Its neighbours decide (terrain_finish).
inline bool terrain_lowest_apart(float lowest, float next, float noise_gap) {
  return noise_gap > 0.0f && !std::isnan(lowest) && (std::isnan(next) || next - lowest > noise_gap);
}
inline float terrain_band_base(float lowest, float next, float noise_gap) {
  return terrain_lowest_apart(lowest, next, noise_gap) ? next : lowest;
}
inline void terrain_low_band(float base, float z, float band, float& sum, float& count) {
  if (!(z >= base) || z > base + band) return;  // below: the lowest left apart; NaN base: alone
  sum += z - base;
  count += 1.0f;
}

// out = min (erode) or max (dilate) of `in` over 2r + 1 cells along each
// row (along_x) or column of an nx x ny grid, cells without data (NaN)
// skipped, NaN where a window has none. `line` holds max(nx, ny) floats;
// `in` and `out` differ. O(cells) whatever r.
void terrain_line_filter(const float* in, float* out, float* line, uint32_t nx, uint32_t ny, uint32_t r,
                         bool along_x, bool erode);

}  // namespace spinhash
