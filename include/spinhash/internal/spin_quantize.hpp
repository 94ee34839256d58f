// Internal interface (host tools may use it; not installed, may change):
// the database's quantised form of a spin image, shared by the core, the
// database builder and the experiments so that all three compute the same
// numbers. The L1 distance between quantised images is a kernel:
// spinhash/internal/l1_distance.hpp.
#pragma once
#include <cstdint>

namespace spinhash {

// q = min(255, round(v * scale)): the database's stored form of a spin image.
void quantize_spin(const float* image, uint32_t dims, float scale, uint8_t* out);

}  // namespace spinhash
