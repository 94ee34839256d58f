// SSE2 spin-image accumulation (every x86-64 CPU): four neighbours per
// register through the radius and support tests, the bin coordinates and
// the four bilinear weights; the votes are then added lane by lane in the
// neighbours' order (float addition is not associative). Each lane does the
// reference's operations in its order (divps and sqrtps round correctly).
#pragma once
#if defined(__SSE2__)
#include <emmintrin.h>

#include <cstdint>

#include "kernels/reference/spin.hpp"
#include "kernels/spin_geometry.hpp"

#define SPINHASH_KERNELS_HAVE_SSE2_SPIN 1

namespace spinhash {
namespace kernels {
namespace sse2 {

inline __m128 madd3(__m128 a0, __m128 b0, __m128 a1, __m128 b1, __m128 a2, __m128 b2) {
  // (a0 * b0 + a1 * b1) + a2 * b2, as the scalar expression rounds it
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a0, b0), _mm_mul_ps(a1, b1)), _mm_mul_ps(a2, b2));
}

inline void spin_accumulate(const SpinGeometry& b, const SpinNeighbours& g, const float* p, const float* n,
                            float* image) {
  const __m128 px = _mm_set1_ps(p[0]), py = _mm_set1_ps(p[1]), pz = _mm_set1_ps(p[2]);
  const __m128 n0 = _mm_set1_ps(n[0]), n1 = _mm_set1_ps(n[1]), n2 = _mm_set1_ps(n[2]);
  const __m128 r2 = _mm_set1_ps(b.r2), cos_support = _mm_set1_ps(b.cos_support_angle);
  const __m128 zero = _mm_setzero_ps(), half = _mm_set1_ps(0.5f), one = _mm_set1_ps(1.0f);
  const __m128 bin_a = _mm_set1_ps(b.bin_a), bin_b = _mm_set1_ps(b.bin_b), radius = _mm_set1_ps(b.radius);
  const __m128 last_a = _mm_set1_ps(b.last_a), last_b = _mm_set1_ps(b.last_b);
  const __m128 row = _mm_set1_ps(static_cast<float>(b.bins_alpha));
  const __m128i one_i = _mm_set1_epi32(1);
  const __m128i bins_a = _mm_set1_epi32(static_cast<int32_t>(b.bins_alpha));
  const __m128i bins_b = _mm_set1_epi32(static_cast<int32_t>(b.bins_beta));
  alignas(16) int32_t at[4], step_a[4], step_b[4];
  alignas(16) float w00[4], w01[4], w10[4], w11[4];
  uint32_t k = 0;
  for (; k + 4u <= g.count; k += 4u) {
    const __m128 ex = _mm_sub_ps(_mm_loadu_ps(g.x + k), px);
    const __m128 ey = _mm_sub_ps(_mm_loadu_ps(g.y + k), py);
    const __m128 ez = _mm_sub_ps(_mm_loadu_ps(g.z + k), pz);
    const __m128 d2 = madd3(ex, ex, ey, ey, ez, ez);
    __m128 keep = _mm_cmple_ps(d2, r2);
    if (b.use_support_angle) {
      const __m128 dot =
          madd3(n0, _mm_loadu_ps(g.nx + k), n1, _mm_loadu_ps(g.ny + k), n2, _mm_loadu_ps(g.nz + k));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(dot, cos_support));  // false for NaN: no normal
    }
    int lanes = _mm_movemask_ps(keep);
    if (lanes == 0) continue;  // most of a gathered cube lies beyond the support sphere
    const __m128 beta = madd3(n0, ex, n1, ey, n2, ez);
    // max(a, 0) is a > 0 ? a : 0 (maxps returns its second operand on NaN);
    // on the clamps below, where a is never NaN nor -0, max and min are clampf.
    const __m128 alpha = _mm_sqrt_ps(_mm_max_ps(_mm_sub_ps(d2, _mm_mul_ps(beta, beta)), zero));
    const __m128 fa = _mm_min_ps(_mm_max_ps(_mm_sub_ps(_mm_div_ps(alpha, bin_a), half), zero), last_a);
    const __m128 fb =
        _mm_min_ps(_mm_max_ps(_mm_sub_ps(_mm_div_ps(_mm_add_ps(beta, radius), bin_b), half), zero), last_b);
    const __m128i i0 = _mm_cvttps_epi32(fa), j0 = _mm_cvttps_epi32(fb);
    const __m128 fi0 = _mm_cvtepi32_ps(i0), fj0 = _mm_cvtepi32_ps(j0);
    const __m128 wa = _mm_sub_ps(fa, fi0), wb = _mm_sub_ps(fb, fj0);
    const __m128 ua = _mm_sub_ps(one, wa), ub = _mm_sub_ps(one, wb);
    _mm_store_ps(w00, _mm_mul_ps(ua, ub));
    _mm_store_ps(w01, _mm_mul_ps(wa, ub));
    _mm_store_ps(w10, _mm_mul_ps(ua, wb));
    _mm_store_ps(w11, _mm_mul_ps(wa, wb));
    // j0 * bins_alpha + i0 in float: exact (at most kMaxSpinDims), and SSE2 has no 32-bit multiply.
    _mm_store_si128(reinterpret_cast<__m128i*>(at), _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(fj0, row), fi0)));
    _mm_store_si128(reinterpret_cast<__m128i*>(step_a),
                    _mm_and_si128(_mm_cmplt_epi32(_mm_add_epi32(i0, one_i), bins_a), one_i));
    _mm_store_si128(reinterpret_cast<__m128i*>(step_b),
                    _mm_and_si128(_mm_cmplt_epi32(_mm_add_epi32(j0, one_i), bins_b), bins_a));
    for (; lanes != 0; lanes &= lanes - 1) {  // lowest lane first: the neighbours' order
      const int l = __builtin_ctz(static_cast<unsigned>(lanes));
      float* cell = image + at[l];
      cell[0] += w00[l];
      cell[step_a[l]] += w01[l];
      cell[step_b[l]] += w10[l];
      cell[step_b[l] + step_a[l]] += w11[l];
    }
  }
  for (; k < g.count; ++k) spin_neighbour(b, g, k, p, n, image);
}

}  // namespace sse2
}  // namespace kernels
}  // namespace spinhash
#endif  // __SSE2__
