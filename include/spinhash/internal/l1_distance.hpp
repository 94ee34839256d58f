// Internal interface (host tools may use it; not installed, may change): the
// L1 distance between two quantised spin images, the kernel the core's LSH
// scan and verification use (firmware-lib/kernels/: a scalar reference and
// SSE2, AVX2 and NEON versions, chosen at compile time; every one gives the
// same integers). Shared by the core, the database builder and the
// experiments so that all three compute the same numbers.
#pragma once
#include <cstdint>

namespace spinhash {

// Exact sum of |a[i] - b[i]| over dims bytes (the same integer on every target).
uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims);

// The L1 distance when it is at most `bound`; otherwise some value above
// `bound` (the scan stops early: most database entries a query feature is
// compared with are far beyond the candidates it keeps).
uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound);

// The kernel this build selected: "reference", "sse2", "avx2" or "neon".
const char* l1_kernel_name();

}  // namespace spinhash
