// The segmentation cell a tile's density asks for. The core links points
// of one object through touching cells of `segment_cell`; a cell narrower
// than the points' spacing leaves them in cells that do not touch, and
// every vehicle falls apart into fragments (at 4 points per m2 a 0.25 m
// cell finds none). The finest cell (SceneConfig::segment_cell, 0.25 m:
// it parts vehicles parked 0.5 m apart) is doubled until it reaches the
// tile's mean point spacing, 1 / sqrt(points per m2): a gap narrower than
// the spacing is not seen anyway. The tile path (tile_stream.hpp) applies
// it to every tile; a survey once for all its tiles, so that neighbours
// segment a shared vehicle alike.
#pragma once
#include <cstdint>

namespace spinhash::pipeline {

// At most two doublings (1 m from 0.25 m): a vehicle is 1.5-2 m wide, and
// a coarser cell joins it to whatever stands within its own width.
constexpr uint32_t kMaxSegmentCellDoublings = 2;

// The cell for a tile of `points_per_m2` (0 or less: unknown, `finest`
// kept). Each doubling keeps `window_core` a whole number of cells, or is
// not taken.
float segment_cell_for_density(float finest, double points_per_m2, double window_core);

// Points per m2 over a tile's bounding box (x y), as `scene` and the
// survey (over all its tiles) measure it: 0 for an empty box. A tile with
// empty parts (water, a swath's edge) is taken as sparser than its points
// lie, and gets a coarser cell.
double tile_density(uint64_t points, double box_area);

}  // namespace spinhash::pipeline
