// NEON spin-image accumulation (aarch64 only): as the SSE2 kernel, four
// neighbours per register; the votes are added lane by lane in the
// neighbours' order. aarch64's vector divide and square root round
// correctly as the scalar ones do. 32-bit Arm NEON has neither, and flushes
// subnormals to zero: armhf keeps the reference.
#pragma once
#if defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>

#include <cstdint>

#include "kernels/reference/spin.hpp"
#include "kernels/spin_geometry.hpp"

#define SPINHASH_KERNELS_HAVE_NEON_SPIN 1

namespace spinhash {
namespace kernels {
namespace neon {

inline float32x4_t madd3(float32x4_t a0, float32x4_t b0, float32x4_t a1, float32x4_t b1, float32x4_t a2,
                         float32x4_t b2) {
  // (a0 * b0 + a1 * b1) + a2 * b2, as the scalar expression rounds it (vmulq, vaddq: never fused)
  return vaddq_f32(vaddq_f32(vmulq_f32(a0, b0), vmulq_f32(a1, b1)), vmulq_f32(a2, b2));
}

// v > 0 ? v : 0 (NaN to 0), as the reference's alpha^2 clamp.
inline float32x4_t positive_or_zero(float32x4_t v) {
  return vbslq_f32(vcgtq_f32(v, vdupq_n_f32(0.0f)), v, vdupq_n_f32(0.0f));
}

inline void spin_accumulate(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                            float* image) {
  const float32x4_t px = vdupq_n_f32(p[0]), py = vdupq_n_f32(p[1]), pz = vdupq_n_f32(p[2]);
  const float32x4_t n0 = vdupq_n_f32(n[0]), n1 = vdupq_n_f32(n[1]), n2 = vdupq_n_f32(n[2]);
  const float32x4_t r2 = vdupq_n_f32(b.r2), cos_support = vdupq_n_f32(b.cos_support_angle);
  const float32x4_t zero = vdupq_n_f32(0.0f), half = vdupq_n_f32(0.5f), one = vdupq_n_f32(1.0f);
  const float32x4_t bin_a = vdupq_n_f32(b.bin_a), bin_b = vdupq_n_f32(b.bin_b),
                    radius = vdupq_n_f32(b.radius);
  const float32x4_t last_a = vdupq_n_f32(b.last_a), last_b = vdupq_n_f32(b.last_b);
  const uint32x4_t one_u = vdupq_n_u32(1u), bins_a = vdupq_n_u32(b.bins_alpha),
                   bins_b = vdupq_n_u32(b.bins_beta);
  const uint32x4_t lane_bits = {1u, 2u, 4u, 8u};
  alignas(16) uint32_t at[4], step_a[4], step_b[4];
  alignas(16) float w00[4], w01[4], w10[4], w11[4];
  uint32_t k = 0;
  for (; k + 4u <= g.count; k += 4u) {
    const float32x4_t ex = vsubq_f32(vld1q_f32(g.x + k), px);
    const float32x4_t ey = vsubq_f32(vld1q_f32(g.y + k), py);
    const float32x4_t ez = vsubq_f32(vld1q_f32(g.z + k), pz);
    const float32x4_t d2 = madd3(ex, ex, ey, ey, ez, ez);
    uint32x4_t keep = vcleq_f32(d2, r2);
    if (b.use_support_angle) {
      const float32x4_t dot =
          madd3(n0, vld1q_f32(g.nx + k), n1, vld1q_f32(g.ny + k), n2, vld1q_f32(g.nz + k));
      keep = vandq_u32(keep, vcgeq_f32(dot, cos_support));  // false for NaN: no normal
    }
    uint32_t lanes = vaddvq_u32(vandq_u32(keep, lane_bits));
    if (lanes == 0u) continue;  // most of a gathered cube lies beyond the support sphere
    const float32x4_t beta = madd3(n0, ex, n1, ey, n2, ez);
    const float32x4_t alpha = vsqrtq_f32(positive_or_zero(vsubq_f32(d2, vmulq_f32(beta, beta))));
    // The clamps: a bin coordinate is never NaN nor -0, where vmaxq and vminq are clampf.
    const float32x4_t fa = vminq_f32(vmaxq_f32(vsubq_f32(vdivq_f32(alpha, bin_a), half), zero), last_a);
    const float32x4_t fb =
        vminq_f32(vmaxq_f32(vsubq_f32(vdivq_f32(vaddq_f32(beta, radius), bin_b), half), zero), last_b);
    const uint32x4_t i0 = vcvtq_u32_f32(fa), j0 = vcvtq_u32_f32(fb);
    const float32x4_t wa = vsubq_f32(fa, vcvtq_f32_u32(i0)), wb = vsubq_f32(fb, vcvtq_f32_u32(j0));
    const float32x4_t ua = vsubq_f32(one, wa), ub = vsubq_f32(one, wb);
    vst1q_f32(w00, vmulq_f32(ua, ub));
    vst1q_f32(w01, vmulq_f32(wa, ub));
    vst1q_f32(w10, vmulq_f32(ua, wb));
    vst1q_f32(w11, vmulq_f32(wa, wb));
    vst1q_u32(at, vmlaq_u32(i0, j0, bins_a));  // j0 * bins_alpha + i0 (integers: exact)
    vst1q_u32(step_a, vandq_u32(vcltq_u32(vaddq_u32(i0, one_u), bins_a), one_u));
    vst1q_u32(step_b, vandq_u32(vcltq_u32(vaddq_u32(j0, one_u), bins_b), bins_a));
    for (; lanes != 0u; lanes &= lanes - 1u) {  // lowest lane first: the neighbours' order
      const int l = __builtin_ctz(lanes);
      float* cell = image + at[l];
      cell[0] += w00[l];
      cell[step_a[l]] += w01[l];
      cell[step_b[l]] += w10[l];
      cell[step_b[l] + step_a[l]] += w11[l];
    }
  }
  for (; k < g.count; ++k) spin_neighbour(b, g, k, p, n, image);
}

}  // namespace neon
}  // namespace kernels
}  // namespace spinhash
#endif  // __ARM_NEON && __aarch64__
