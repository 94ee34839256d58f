// Terrain under a cut-out object, on sloped and uneven ground (not in the
// paper; the single-object path of Recognizer; whole tiles use the terrain
// classifier of geometry/terrain.hpp, which needs a tile's context). Every airborne scan of a vehicle holds
// the ground around it, which no model has: its flat spin images crowd the candidates and its points count as
// outliers in eq. 7. Real terrain is rarely level within the clearance over a vehicle's footprint, so the
// ground is not a height slab: the lowest point of each cell of a grid over the footprint, a plane fitted to
// those lowest points by trimmed least squares (objects rise above it and are trimmed), and per cell the mean
// level of the ground points near that plane (bumps, curbs), whose spread measures the noise. Points
// within a few sigma of that noise above the local level are ground. z is up (georeferenced input). Every
// threshold is a field of GroundParams (stage_fields.h).
#pragma once
#include <cstdint>

#include "spinhash/config.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {

// The grid over the cloud's footprint: kObjectGroundGridSide cells per axis
// (limits.hpp), each GroundParams::min_ground_cell wide or, for a sparse
// scan, up to max_ground_cell.
constexpr uint32_t kTerrainGridSide = kObjectGroundGridSide;
constexpr uint32_t kTerrainCells = kObjectGroundCells;
// A vehicle's lower body lies within the ground band too, and seen from the
// air the ground beside a vehicle has nothing above it while its lower sides
// stand under the rest of the body. So the band's top part is kept in a
// column (a cell of a kColumnSplit times finer grid) whose highest point
// rises GroundParams::body_above over the band. Only its top: the oblique
// views see ground under and beside the body too.
constexpr uint32_t kColumnSplit = 2;  // 0.25 m columns in a dense scan's 0.5 m cells
constexpr uint32_t kColumnCells = kTerrainCells * kColumnSplit * kColumnSplit;
// lowest point, mean, spread, count per cell; highest point per column
constexpr uint32_t kObjectGroundScratchFloats = 4u * kTerrainCells + kColumnCells;

// What the terrain says about the object standing on it (when `found`): the
// height of its top above the local terrain, the measure a survey takes
// best (the roof is sampled from above, the terrain around the vehicle by
// many points), and the terrain's roughness, the scan's noise.
struct TerrainUnder {
  bool found = false;
  float top = 0.0f;    // m: the second highest kept point above its terrain level (one spike is noise)
  float sigma = 0.0f;  // m: the ground points' spread about their cells' levels
  float band = 0.0f;   // m above the terrain level up to which points were dropped as ground
};

// When the n points stand on terrain, drops those within clearance_sigmas of
// the ground's measured roughness above it (at least min_clearance, at most
// ground_clearance m), compacting xyz in place, and returns how many went;
// otherwise (no terrain found, the stage off, clearance 0) keeps every point
// and returns 0. `scratch` holds kObjectGroundScratchFloats floats. O(n)
// with a bounded number of passes. `terrain`, when given, says what the
// terrain tells of the object.
uint32_t remove_object_ground(float* xyz, uint32_t n, const GroundParams& params, float* scratch,
                              TerrainUnder* terrain = nullptr);

}  // namespace spinhash
