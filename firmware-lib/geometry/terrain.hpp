// Terrain under a cut-out object, on sloped and uneven ground (not in the
// paper). Every airborne scan of a vehicle holds the ground around it, which
// no model has: its flat spin images crowd the candidates and its points
// count as outliers in eq. 7. Real terrain is rarely level within the
// clearance over a vehicle's footprint, so the ground is not a height slab:
// the lowest point of each cell of a grid over the footprint, a plane fitted
// to those lowest points by trimmed least squares (objects rise above it and
// are trimmed), and per cell the mean level of the ground points near that
// plane (bumps, curbs). Points within the clearance above the local level
// are ground. z is up (georeferenced input).
#pragma once
#include <cstdint>

namespace spinhash {

constexpr uint32_t kTerrainGridSide = 32;  // cells per axis over the cloud's footprint
constexpr uint32_t kTerrainCells = kTerrainGridSide * kTerrainGridSide;
constexpr float kMinTerrainCell = 0.5f;       // m: smaller cells see too few ground points
constexpr uint32_t kTerrainFitRounds = 5;     // trimmed plane fits
constexpr uint32_t kTerrainCoarseRounds = 2;  // the first rounds trim only what rises a lot
constexpr float kObjectCellRise = 0.5f;       // m: a cell whose lowest point rises more holds an object
constexpr float kGroundCellRise = 0.2f;       // m: ... at most this much (noise, bumps): ground
constexpr float kGroundBand = 0.2f;           // m above a ground cell's lowest point: its ground points
constexpr float kMaxTerrainSlopeDeg = 35.0f;  // steeper "ground" is a wall or a vehicle's side
constexpr float kMinGroundShare = 0.35f;      // points on the terrain that say "there is ground here"
constexpr float kMinGroundCellShare = 0.5f;   // occupied cells that are ground, likewise
constexpr uint32_t kTerrainScratchFloats = 3u * kTerrainCells;  // lowest point, level sum, level count

// When the n points stand on terrain, drops those within `clearance` m above
// it (compacting xyz in place) and returns how many went; otherwise (no
// terrain found, clearance 0) keeps every point and returns 0. `scratch`
// holds kTerrainScratchFloats floats. O(n) with a bounded number of passes.
uint32_t remove_terrain(float* xyz, uint32_t n, float clearance, float* scratch);

}  // namespace spinhash
