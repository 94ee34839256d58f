// Simulated occlusion: a vertical slab (wall, tree trunk) that hides a
// chosen fraction of the object's points.
#pragma once

#include "mesh/seeded_random.hpp"

#include <cstdint>
#include <vector>

namespace spinhash::host {

// Marks in *keep (one flag per point of xyz) the object points inside a
// vertical slab of random horizontal orientation and position that holds
// round(fraction * object points); ground points (on_object == 0) are kept.
void apply_slab_occluder(const std::vector<double>& xyz, const std::vector<uint8_t>& on_object,
                         double fraction, SeededRandom* rng, std::vector<uint8_t>* keep);

}  // namespace spinhash::host
