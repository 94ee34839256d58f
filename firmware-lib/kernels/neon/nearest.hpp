// NEON nearest-feature kernels (aarch64 only): as the SSE2 kernels, one
// query feature per call, its three coordinates in the lanes of one
// register, each lane running the reference's arithmetic. Eigen's 3x3
// product on aarch64 computes rows 0-1 as one 2-lane packet with fused
// multiply-adds, fma(r2, e2, fma(r1, e1, r0 e0)), and row 2 as the scalar
// r0 e0 + (r1 e1 + r2 e2) (vmulq, vaddq: never fused under
// -ffp-contract=off); the kernel does both and keeps each where Eigen
// does. 32-bit Arm NEON flushes subnormals to zero and has no vector
// division: armhf keeps the reference.
#pragma once
#if defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>

#include <cstdint>

#include "kernels/nearest_geometry.hpp"

#define SPINHASH_KERNELS_HAVE_NEON_NEAREST 1

namespace spinhash {
namespace kernels {
namespace neon {

// (p[0], p[1], p[2], 0): never reads p[3], which may lie past the array.
inline float32x4_t load3(const float* p) {
  return vcombine_f32(vld1_f32(p), vset_lane_f32(p[2], vdup_n_f32(0.0f), 0));
}

// R^T e as Eigen's product rounds it on aarch64 (see above).
inline float32x4_t frame_rows(const FrameChange& f, float32x4_t e) {
  const float32x4_t c0 = vld1q_f32(f.col[0]), c1 = vld1q_f32(f.col[1]), c2 = vld1q_f32(f.col[2]);
  const float32x4_t a0 = vmulq_laneq_f32(c0, e, 0);
  const float32x4_t fused = vfmaq_laneq_f32(vfmaq_laneq_f32(a0, c1, e, 1), c2, e, 2);
  const float32x4_t plain = vaddq_f32(a0, vaddq_f32(vmulq_laneq_f32(c1, e, 1), vmulq_laneq_f32(c2, e, 2)));
  return vcombine_f32(vget_low_f32(fused), vget_high_f32(plain));
}

// x and n: four floats each (lane 3 written).
inline void to_model_frame(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  vst1q_f32(x, frame_rows(f, vsubq_f32(load3(q), vld1q_f32(f.t))));
  vst1q_f32(n, frame_rows(f, load3(qn)));
}

// x: four floats (lane 3 ignored); v: four slots (lane 3 written).
inline bool field_voxel(const FieldBox& b, const float* x, uint32_t* v) {
  const float32x4_t t = vdivq_f32(vsubq_f32(vld1q_f32(x), vld1q_f32(b.lo)), vdupq_n_f32(b.cell));
  const uint32x4_t lane3 = {0u, 0u, 0u, ~0u};  // lane 3 always passes
  const uint32x4_t inside = vandq_u32(vcgeq_f32(t, vdupq_n_f32(0.0f)), vcltq_f32(t, vld1q_f32(b.dims)));
  if (vminvq_u32(vorrq_u32(inside, lane3)) == 0u) return false;
  vst1q_u32(v, vcvtq_u32_f32(t));  // truncates toward zero, as the reference's conversion
  return true;
}

}  // namespace neon
}  // namespace kernels
}  // namespace spinhash
#endif  // __ARM_NEON && __aarch64__
