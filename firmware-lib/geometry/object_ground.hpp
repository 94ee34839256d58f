// Terrain under a cut-out object, on sloped and uneven ground (not in the
// paper; the single-object path of Recognizer; whole tiles use the terrain
// classifier of geometry/terrain.hpp, which needs a tile's context). Every airborne scan of a vehicle holds
// the ground around it, which no model has: its flat spin images crowd the candidates and its points count as
// outliers in eq. 7. Real terrain is rarely level within the clearance over a vehicle's footprint, so the
// ground is not a height slab: the lowest point of each cell of a grid over the footprint, a plane fitted to
// those lowest points by trimmed least squares (objects rise above it and are trimmed), and per cell the mean
// level of the ground points near that plane (bumps, curbs), whose spread measures the noise. Points
// within 4.5 sigma of that noise above the local level are ground. z is up (georeferenced input).
#pragma once
#include <cstdint>

namespace spinhash {

constexpr uint32_t kTerrainGridSide = 32;  // cells per axis over the cloud's footprint
constexpr uint32_t kTerrainCells = kTerrainGridSide * kTerrainGridSide;
constexpr float kMinTerrainCell = 0.5f;  // m: smaller cells see too few ground points
constexpr float kMaxTerrainCell = 1.0f;  // m: the coarsest cells a sparse scan gets
// Points per occupied cell, on average, at least: sparser scans (0.15 m
// spacing: about 12 in a 0.5 m cell) get coarser cells, so that the cells
// along the footprint's edge, partly covered, still catch the
// kMinRoughnessPoints ground points that measure their spread.
constexpr float kMinPointsPerCell = 25.0f;
constexpr uint32_t kTerrainFitRounds = 5;     // trimmed plane fits
constexpr uint32_t kTerrainCoarseRounds = 2;  // the first rounds trim only what rises a lot
constexpr float kObjectCellRise = 0.5f;       // m: a cell whose lowest point rises more holds an object
constexpr float kGroundCellRise = 0.2f;       // m: ... at most this much (noise, bumps): ground
constexpr float kRoughnessBand = 0.5f;        // m above a ground cell's lowest point: its ground points
constexpr uint32_t kMinRoughnessPoints = 5;   // fewer ground points: no spread measured in that cell
constexpr float kCleanSpreadFactor = 2.0f;    // spread above this times the median: an object stands there
constexpr float kSpreadSlack = 0.01f;         // m added to that bound (noise-free ground has no spread)
constexpr float kClearanceSigmas = 4.5f;      // this many sigma of the ground's roughness above it is ground
constexpr float kMinClearance = 0.05f;        // m: at least this much is ground (noise-free clouds)
constexpr float kMaxGroundRoughness =
    0.11f;  // m: rougher "ground" (sigma) is an object's side (10 cm noise: 0.095)
constexpr float kMinCleanBorderShare =
    0.45f;  // of the footprint's border cells: terrain reaches past the object
constexpr float kBelowTerrainSigmas = 4.0f;     // points deeper below the terrain than this many sigma ...
constexpr float kMinBelowTerrain = 0.3f;        // ... (or this many m) say it is no terrain ...
constexpr float kMaxBelowTerrainShare = 0.02f;  // ... when more than this share of the points lie there
constexpr float kMaxTerrainSlopeDeg =
    18.0f;  // steeper "ground" is a vehicle's side or cargo bed (terrain: to 15)
constexpr float kMinObjectGroundShare = 0.15f;  // points on the terrain that say "there is ground here"
constexpr float kMinGroundCellShare = 0.3f;     // occupied cells that are ground, likewise
// A vehicle's lower body lies within the ground band too: a low sports car
// (0.74 m) lost 45 % of its features with it (issue 28). Seen from the air,
// the ground beside a vehicle has nothing above it, while its lower sides
// stand under the rest of the body. So the band's top part is kept in a
// column (a cell of a kColumnSplit times finer grid) whose highest point
// rises kBodyAbove over the band. Only its top: the oblique views see ground
// under and beside the body too, and keeping the whole band there lost
// (docs/results.md 11g).
constexpr uint32_t kColumnSplit = 2;  // 0.25 m columns in a dense scan's 0.5 m cells
constexpr uint32_t kColumnCells = kTerrainCells * kColumnSplit * kColumnSplit;
constexpr float kBodyAbove = 0.3f;     // m above the band: a body, not ground noise (10 cm noise: > 5 sigma)
constexpr float kBandKeptFrom = 0.7f;  // of the band's height: the part kept under a body
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

// When the n points stand on terrain, drops those within kClearanceSigmas of the
// ground's measured roughness above it (at least kMinClearance, at most
// `clearance` m), compacting xyz in place, and returns how many went;
// otherwise (no terrain found, clearance 0) keeps every point and returns 0. `scratch`
// holds kObjectGroundScratchFloats floats. O(n) with a bounded number of passes.
// `terrain`, when given, says what the terrain tells of the object.
uint32_t remove_object_ground(float* xyz, uint32_t n, float clearance, float* scratch,
                              TerrainUnder* terrain = nullptr);

}  // namespace spinhash
