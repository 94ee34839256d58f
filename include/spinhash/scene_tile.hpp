// A tile of known extent through SceneStream: the one plan of the tile API
// (SceneRecognizer, scene.hpp) and of the host's files (`spinhash scene`,
// the survey, Python). The frame: heading +x, its origin on the lattice of
// window cores below the tile's min corner (so that adjacent tiles' windows
// line up), z at the tile's lowest point. Across (y) the tile is cut into
// bands of SceneConfig::band_columns window columns; each band is a line of
// its own (SceneStream::reset with the band's origin) that owns its columns
// and sees window_margin beyond them, so the buffer never holds a row
// across the whole tile. Along (x) a band's points are pushed in rows of
// SceneConfig::row_depth, in order; the points of a row in any order (the
// stream's max_lag). A band whose columns and object margins hold no point
// reports nothing and may be skipped.
#pragma once
#include <cstdint>

#include "spinhash/scene_stream.hpp"

namespace spinhash {

// The stream config every band of a tile runs with: the band's frame
// (heading +x, origin given per band), its owned columns [0, band width)
// and swath (window_margin beyond them), the lag of a row, no limit on
// jumps or heights short of kMaxStreamExtent (the tile's extent is known),
// and a buffer of max_buffered_points (0: as many as a band's rows hold at
// the density that fills a window's max_tile_points). Independent of the
// tile's extent.
StreamConfig tile_stream_config(const SceneConfig& scene, uint32_t max_buffered_points) noexcept;

struct TilePlan {
  double origin[3] = {0.0, 0.0, 0.0};  // band 0's frame origin
  double band_width = 0.0;             // m across: band b's origin is b band widths further in y
  double row_depth = 0.0;              // m along x
  double object_margin = 0.0;          // m: a band gathers its columns and this much beyond
  uint32_t bands = 0;                  // over the tile's extent across
};

// The plan of a tile whose finite points lie within [lo, hi] (x y z; lo <= hi).
TilePlan plan_tile(const SceneConfig& scene, const double* lo, const double* hi) noexcept;
// Band b's frame origin (x y z).
void tile_band_origin(const TilePlan& plan, uint32_t b, double* origin) noexcept;
// The first band whose columns or object margins hold y (bands may overlap
// there); plan.bands when none.
uint32_t tile_band_gathering(const TilePlan& plan, double y) noexcept;
// The row a point at x is pushed in: rows of row_depth from x = 0 (the
// same rows whatever the tile, as the host's AlongTrackOrder cuts them).
int64_t tile_row(const TilePlan& plan, double x) noexcept;

// Cells of a grid of `cell` over w x h m (with the snap's extra cells),
// at most kMaxSceneGridCells.
uint32_t scene_grid_cells(double w, double h, float cell) noexcept;
// The scene's grids at least as large as a band's strip of windows (its
// terrain) and a window's gather (its segmentation) need.
void fit_tile_grids(SceneConfig* scene) noexcept;

}  // namespace spinhash
