// Ground removal for airborne queries (not in the paper). Every airborne
// scan of a vehicle holds the ground around it, which no model has: its flat
// spin images crowd the candidates and its points count as outliers in eq. 7.
// The terrain classifier (geometry/terrain.hpp) finds it on slopes, bumps and
// curbs too; a cloud with too little ground to be sure is left whole.
#pragma once
#include <cstdint>

#include "geometry/terrain.hpp"

namespace spinhash {

constexpr float kMinGroundShare = 0.35f;         // ground share that says "there is ground here"
constexpr float kMinOpenGroundShare = 0.2f;      // share of the occupied cells holding ground only:
                                                 // ground reaches beyond the object (a box's bottom does not)
constexpr float kMaxGroundStepSlope = 0.35f;     // m per m between neighbouring ground cells (~19 degrees)
constexpr float kMaxGroundStepExtra = 0.2f;      // m on top: noise and curbs
constexpr float kMaxSteepGroundShare = 0.05f;    // more steep neighbour pairs: not terrain (a vehicle's
                                                 // hood and sides taken for ground when it has none)
constexpr uint32_t kQueryTerrainCells = 4096;    // 64 x 64 cells: a query of 32 m at 0.5 m
constexpr float kQueryTerrainCell = 0.5f;        // m: coarser only when the query is wider than 32 m

// Drops the points at most `clearance` m above the local terrain (compacting
// xyz in place) when they are at least kMinGroundShare of the n points and
// at least kMinOpenGroundShare of the occupied cells hold nothing else and
// at most kMaxSteepGroundShare of the neighbouring ground cells differ by
// more than a terrain slope allows, and
// returns how many went; otherwise keeps every point and returns 0. `grid`
// holds kQueryTerrainCells cells; height and ground hold n entries (scratch).
uint32_t remove_ground(float* xyz, uint32_t n, float clearance, TerrainGrid& grid, float* height, uint8_t* ground);

}  // namespace spinhash
