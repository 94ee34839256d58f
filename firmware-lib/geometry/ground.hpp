// Level-ground removal for airborne queries (not in the paper). Every
// airborne scan of a vehicle holds the ground around it, which no model
// has: its flat spin images crowd the candidates and its points count as
// outliers in eq. 7. With z up (georeferenced input), the ground is the
// dense horizontal slab at the bottom of the cloud.
#pragma once
#include <cstdint>

namespace spinhash {

constexpr uint32_t kGroundHistogramBins = 1024;  // z histogram: ~1 cm bins over a 10 m tall cloud
constexpr float kGroundPercentile = 0.05f;       // the ground holds far more than 5% of the points
constexpr float kMinGroundShare = 0.35f;         // slab share that says "there is ground here"

// When at least kMinGroundShare of the n points lie at most `clearance` m
// above the kGroundPercentile height of z, drops those points (compacting
// xyz in place) and returns how many went; otherwise keeps every point and
// returns 0. `histogram` holds kGroundHistogramBins counters. O(n).
uint32_t remove_level_ground(float* xyz, uint32_t n, float clearance, uint32_t* histogram);

}  // namespace spinhash
