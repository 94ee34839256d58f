// Terrain classification for airborne clouds on sloped, uneven ground (not in
// the paper): a lowest-points grid filtered by a progressive morphological
// opening (Zhang et al. 2003, the PMF of PDAL), then each point's height
// above the local terrain surface. Opening preserves planes of any slope and
// steps (curbs), and removes anything narrower than the window; a cell is
// off the ground when the opening lowers it by more than the slope allowance
// of that window. Memory: a few floats per grid cell, carved by the caller.
#pragma once
#include <cmath>
#include <cstdint>

#include "spinhash/arena.hpp"
#include "spinhash/status.hpp"

namespace spinhash {

constexpr float kTerrainLowBand = 0.3f;     // m: cell value = mean of the points this close to its lowest
constexpr uint32_t kMaxTerrainWindows = 8;  // PMF windows (half-widths 1, 2, 4, ... cells)

struct TerrainParams {
  float cell = 0.5f;            // m: grid cell edge
  float max_window = 24.0f;     // m: largest opening window (wider than any building to remove)
  float slope = 0.35f;          // s of PMF: rise per m allowed between windows (0.35 ~ 19 degrees)
  float dh0 = 0.2f;             // m: dh_0, height tolerance of the smallest window
  float dh_max = 2.5f;          // m: dh_max, the cap of the height tolerance
  float ground_height = 0.25f;  // m: a point at most this far above the terrain is ground
};

// The grid over a cloud's xy bounding box; its buffers come from an Arena.
struct TerrainGrid {
  uint32_t max_cells = 0;
  float* value = nullptr;    // per cell: low mean z (NaN: no point)
  float* surface = nullptr;  // per cell: terrain z (NaN: no data within the largest window)
  float* scratch = nullptr;  // per cell: opening buffers
  float* opened = nullptr;
  float* line = nullptr;          // one row or column: the opening's running extremes
  uint8_t* off_ground = nullptr;  // per cell: 1 when the filter flagged it
  uint32_t nx = 0, ny = 0;
  float x0 = 0.0f, y0 = 0.0f;  // min corner of cell (0, 0)
  float cell = 0.5f;

  // Carves the buffers for `max_cells` cells (counting when the arena does).
  void carve(Arena& arena, uint32_t cells);
};

struct TerrainStats {
  uint32_t cells = 0;          // grid cells used (nx * ny)
  uint32_t cells_ground = 0;   // non-empty cells the filter kept as ground
  uint32_t points_ground = 0;  // points at most ground_height above the terrain
  uint32_t windows = 0;        // PMF windows run
};

// Classifies the n points of xyz (finite, in a local frame, z up): height[i]
// = z - terrain(x, y); ground[i] = 1 when height[i] <= params.ground_height.
// kTileTooLarge when the footprint needs more than grid.max_cells cells (nothing
// written), kInvalidArgument on a bad parameter. O(n + cells * max_window/cell).
Status classify_terrain(const float* xyz, uint32_t n, const TerrainParams& params, TerrainGrid& grid,
                        float* height, uint8_t* ground, TerrainStats* stats);

// classify_terrain in steps, for a grid that several windows share (a strip
// of a scene's row of windows) over points that are not in one array. The
// same operations in the same order: begin over the points' footprint (x, y
// bounds; false when it needs more cells than carved), every point through
// add_lowest, then every point again, in the same order, through
// add_low_band, finish (returns the PMF windows run), then the heights of
// any points within the footprint (returns how many are ground).
bool terrain_begin(TerrainGrid& grid, float cell, const float* lo, const float* hi);
// Or begin over nx x ny cells from (x0, y0), a multiple of `cell`, and put
// each cell's sums (terrain_lowest, then terrain_low_band, over its points)
// with terrain_put_cell: the stream keeps its cells' sums, not the points.
bool terrain_begin_cells(TerrainGrid& grid, float cell, float x0, float y0, uint32_t nx, uint32_t ny);
void terrain_put_cell(TerrainGrid& grid, uint32_t ix, uint32_t iy, float lowest, float band_sum,
                      float band_count);
void terrain_add_lowest(TerrainGrid& grid, const float* p);
void terrain_add_low_band(TerrainGrid& grid, const float* p);
uint32_t terrain_finish(TerrainGrid& grid, const TerrainParams& params, uint32_t* cells_ground);
uint32_t terrain_heights(const TerrainGrid& grid, const float* xyz, uint32_t n, float ground_height,
                         float* height, uint8_t* ground);

// Terrain z at (x, y): bilinear over the cell centres around it, skipping
// cells without data (the point's own cell always has some).
float terrain_height_at(const TerrainGrid& grid, float x, float y);

bool terrain_params_valid(const TerrainParams& p);

// A cell's sums, point by point: its lowest z (NaN: none yet), then, once
// that is final, the points within kTerrainLowBand of it (relative to it:
// small sums, no float drift). The cell's value is lowest + sum / count.
inline void terrain_lowest(float& lowest, float z) {
  if (std::isnan(lowest) || z < lowest) lowest = z;
}
inline void terrain_low_band(float lowest, float z, float& sum, float& count) {
  if (z > lowest + kTerrainLowBand) return;
  sum += z - lowest;
  count += 1.0f;
}

// out = min (erode) or max (dilate) of `in` over 2r + 1 cells along each
// row (along_x) or column of an nx x ny grid, cells without data (NaN)
// skipped, NaN where a window has none. `line` holds max(nx, ny) floats;
// `in` and `out` differ. O(cells) whatever r.
void terrain_line_filter(const float* in, float* out, float* line, uint32_t nx, uint32_t ny, uint32_t r,
                         bool along_x, bool erode);

}  // namespace spinhash
