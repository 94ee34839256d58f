// The nearest-feature kernels verification uses (match/likelihood.cpp: a
// query feature into the model frame, its field voxel), chosen at compile
// time as the L1 and moments kernels are (kernels/l1_select.hpp,
// kernels/moments_select.hpp): SSE2 on x86-64 (without -mfma), NEON on
// aarch64, else the portable reference (bare-metal Cortex-M, armhf).
// SPINHASH_KERNELS_REFERENCE forces the reference.
#pragma once
#include "kernels/nearest_geometry.hpp"
#include "kernels/neon/nearest.hpp"
#include "kernels/reference/nearest.hpp"
#include "kernels/sse2/nearest.hpp"

namespace spinhash {
namespace kernels {

#if defined(SPINHASH_KERNELS_REFERENCE)
namespace nearest_selected = reference;
#elif defined(SPINHASH_KERNELS_HAVE_SSE2_NEAREST)
namespace nearest_selected = sse2;
#define SPINHASH_KERNELS_NEAREST_SIMD 1
#elif defined(SPINHASH_KERNELS_HAVE_NEON_NEAREST)
namespace nearest_selected = neon;
#define SPINHASH_KERNELS_NEAREST_SIMD 1
#else
namespace nearest_selected = reference;
#endif

// Query feature (position q, normal qn) in the model frame. x and n: four
// floats each, lanes 0-2 the answer, lane 3 the kernel's.
inline void to_model_frame(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  nearest_selected::to_model_frame(f, q, qn, x, n);
}

// The field voxel of x[0..2] (x: four floats); v: four slots, v[0..2] the
// voxel when true.
inline bool field_voxel(const FieldBox& b, const float* x, uint32_t* v) {
  return nearest_selected::field_voxel(b, x, v);
}

}  // namespace kernels
}  // namespace spinhash
