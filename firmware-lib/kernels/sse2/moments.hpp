// SSE2 neighbour moments (every x86-64 CPU): the radius test four
// neighbours per register; then each neighbour that passes, in the
// neighbourhood's order, adds its offsets and their products to the nine
// sums held in three registers (lane by lane each sum takes the
// reference's additions in its order; x * y and y * x round alike).
#pragma once
#if defined(__SSE2__)
#include <emmintrin.h>

#include <cstdint>

#include "kernels/moments_geometry.hpp"

#define SPINHASH_KERNELS_HAVE_SSE2_MOMENTS 1

namespace spinhash {
namespace kernels {
namespace sse2 {

// (ex, ey, ez, 0) of lane l of the offsets stored in e[0..11].
inline __m128 lane_offset(const float* e, int l) {
  const __m128 xy = _mm_unpacklo_ps(_mm_load_ss(e + l), _mm_load_ss(e + 4 + l));
  return _mm_movelh_ps(xy, _mm_load_ss(e + 8 + l));
}

// v's lanes in kOrder (_MM_SHUFFLE), by pshufd: SSE2's two-operand shufps
// would first copy v, which every neighbour needs three times.
template <int kOrder>
inline __m128 permute(__m128 v) {
  return _mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(v), kOrder));
}

inline void moments_accumulate(const MomentsNeighbours& g, const float* q, float r2, NeighbourMoments* m) {
  const __m128 qx = _mm_set1_ps(q[0]), qy = _mm_set1_ps(q[1]), qz = _mm_set1_ps(q[2]);
  const __m128 r2v = _mm_set1_ps(r2);
  __m128 s = _mm_setr_ps(m->s[0], m->s[1], m->s[2], 0.0f);
  __m128 a = _mm_setr_ps(m->xx, m->xy, m->xz, 0.0f);  // += dx * (dx, dy, dz)
  __m128 b = _mm_setr_ps(m->yy, m->yz, m->zz, 0.0f);  // += (dy, dz, dz) * (dy, dy, dz)
  uint32_t count = m->count;
  alignas(16) float e[12];  // ex[4], ey[4], ez[4] of one block
  uint32_t k = 0;
  for (; k + 4u <= g.count; k += 4u) {
    const __m128 ex = _mm_sub_ps(_mm_loadu_ps(g.x + k), qx);
    const __m128 ey = _mm_sub_ps(_mm_loadu_ps(g.y + k), qy);
    const __m128 ez = _mm_sub_ps(_mm_loadu_ps(g.z + k), qz);
    // (ex * ex + ey * ey) + ez * ez, as the scalar expression rounds it
    const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(ex, ex), _mm_mul_ps(ey, ey)), _mm_mul_ps(ez, ez));
    int lanes = _mm_movemask_ps(_mm_cmple_ps(d2, r2v));
    if (lanes == 0) continue;  // most of a gathered 3 x 3 x 3 block of cells lies beyond the radius
    _mm_store_ps(e, ex);
    _mm_store_ps(e + 4, ey);
    _mm_store_ps(e + 8, ez);
    for (; lanes != 0; lanes &= lanes - 1) {  // lowest lane first: the neighbours' order
      const __m128 d = lane_offset(e, __builtin_ctz(static_cast<unsigned>(lanes)));
      s = _mm_add_ps(s, d);
      a = _mm_add_ps(a, _mm_mul_ps(d, permute<_MM_SHUFFLE(3, 0, 0, 0)>(d)));
      b = _mm_add_ps(b, _mm_mul_ps(permute<_MM_SHUFFLE(3, 2, 2, 1)>(d), permute<_MM_SHUFFLE(3, 2, 1, 1)>(d)));
      ++count;
    }
  }
  alignas(16) float out[12];
  _mm_store_ps(out, s);
  _mm_store_ps(out + 4, a);
  _mm_store_ps(out + 8, b);
  m->s[0] = out[0], m->s[1] = out[1], m->s[2] = out[2];
  m->xx = out[4], m->xy = out[5], m->xz = out[6];
  m->yy = out[8], m->yz = out[9], m->zz = out[10];
  m->count = count;
  for (; k < g.count; ++k) moments_neighbour(g, k, q, r2, m);
}

}  // namespace sse2
}  // namespace kernels
}  // namespace spinhash
#endif  // __SSE2__
