// NEON neighbour moments (aarch64 only): as the SSE2 kernel, the radius
// test four neighbours per register, then each neighbour that passes, in
// the neighbourhood's order, adds its offsets and their products to the
// sums held lane by lane (x * y and y * x round alike). 32-bit Arm NEON
// flushes subnormals to zero: armhf keeps the reference.
#pragma once
#if defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>

#include <cstdint>

#include "kernels/moments_geometry.hpp"

#define SPINHASH_KERNELS_HAVE_NEON_MOMENTS 1

namespace spinhash {
namespace kernels {
namespace neon {

inline void moments_accumulate(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  const float32x4_t qx = vdupq_n_f32(q[0]), qy = vdupq_n_f32(q[1]), qz = vdupq_n_f32(q[2]);
  const float32x4_t r2v = vdupq_n_f32(r2);
  const uint32x4_t lane_bits = {1u, 2u, 4u, 8u};
  // Lanes 0-2 of each: s (dx, dy, dz); a dx * (dx, dy, dz); b dy * (dx, dy, dz);
  // c dz * (dx, dy, dz). Of b and c only yy, yz and zz are kept.
  float32x4_t s = {m->s[0], m->s[1], m->s[2], 0.0f};
  float32x4_t a = {m->xx, m->xy, m->xz, 0.0f};
  float32x4_t b = {0.0f, m->yy, m->yz, 0.0f};
  float32x4_t c = {0.0f, 0.0f, m->zz, 0.0f};
  uint32_t count = m->count;
  // One block's offsets interleaved (ex0, ey0, ez0, ex1, ...), and a zero
  // past them: the fourth lane of the last neighbour's load.
  float e[13];
  e[12] = 0.0f;
  uint32_t k = 0;
  for (; k + 4u <= g.count; k += 4u) {
    float32x4x3_t ev;
    ev.val[0] = vsubq_f32(vld1q_f32(g.x + k), qx);
    ev.val[1] = vsubq_f32(vld1q_f32(g.y + k), qy);
    ev.val[2] = vsubq_f32(vld1q_f32(g.z + k), qz);
    // (ex * ex + ey * ey) + ez * ez, as the scalar expression rounds it (vmulq, vaddq: never fused)
    const float32x4_t d2 =
        vaddq_f32(vaddq_f32(vmulq_f32(ev.val[0], ev.val[0]), vmulq_f32(ev.val[1], ev.val[1])),
                  vmulq_f32(ev.val[2], ev.val[2]));
    uint32_t lanes = vaddvq_u32(vandq_u32(vcleq_f32(d2, r2v), lane_bits));
    if (lanes == 0u) continue;  // most of a gathered 3 x 3 x 3 block of cells lies beyond the radius
    vst3q_f32(e, ev);
    for (; lanes != 0u; lanes &= lanes - 1u) {  // lowest lane first: the neighbours' order
      const float32x4_t d = vld1q_f32(e + 3 * __builtin_ctz(lanes));  // lane 3: ignored
      s = vaddq_f32(s, d);
      a = vaddq_f32(a, vmulq_laneq_f32(d, d, 0));
      b = vaddq_f32(b, vmulq_laneq_f32(d, d, 1));
      c = vaddq_f32(c, vmulq_laneq_f32(d, d, 2));
      ++count;
    }
  }
  m->s[0] = vgetq_lane_f32(s, 0), m->s[1] = vgetq_lane_f32(s, 1), m->s[2] = vgetq_lane_f32(s, 2);
  m->xx = vgetq_lane_f32(a, 0), m->xy = vgetq_lane_f32(a, 1), m->xz = vgetq_lane_f32(a, 2);
  m->yy = vgetq_lane_f32(b, 1), m->yz = vgetq_lane_f32(b, 2), m->zz = vgetq_lane_f32(c, 2);
  m->count = count;
  for (; k < g.count; ++k) moments_neighbour(g, k, q, r2, m);
}

}  // namespace neon
}  // namespace kernels
}  // namespace spinhash
#endif  // __ARM_NEON && __aarch64__
