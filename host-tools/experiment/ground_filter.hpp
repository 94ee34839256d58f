// The simplest airborne ground removal, to measure what removing the ground
// before recognition buys (not part of the recognizer): level ground is
// assumed; its height is a low percentile of the points' z, and every point
// within a clearance above it is dropped (with the bottom of the wheels).
#pragma once
#include <cstddef>
#include <vector>

namespace spinhash::experiment {

constexpr double kGroundPercentile = 0.05;  // the ground holds far more than 5% of the points
constexpr double kGroundClearance = 0.25;   // m: 5 sigma of the 5 cm noise

// Removes the ground points from xyz (x y z triples); returns how many went.
size_t remove_level_ground(std::vector<double>* xyz);

}  // namespace spinhash::experiment
