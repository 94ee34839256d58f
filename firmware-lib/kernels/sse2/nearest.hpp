// SSE2 nearest-feature kernels (every x86-64 CPU): one query feature per
// call, its three coordinates in the lanes of one register. Each lane runs
// the reference's expression for its row or axis (the same products, the
// same association, the same comparisons), so the answers are the
// reference's bit for bit. Without FMA, Eigen's 3x3 product is scalar and
// sums each row r0 e0 + (r1 e1 + r2 e2); with FMA (-mfma) it fuses, and
// the reference is kept.
#pragma once
#if defined(__SSE2__) && !defined(__FMA__)
#include <emmintrin.h>

#include <cstdint>

#include "kernels/nearest_geometry.hpp"
#include "spinhash/limits.hpp"

#define SPINHASH_KERNELS_HAVE_SSE2_NEAREST 1

namespace spinhash {
namespace kernels {
namespace sse2 {

// cvttps2dq is exact for voxel coordinates below 2^31.
static_assert(kMaxFieldVoxelsPerModel < (1u << 31), "a voxel index must fit an int32 lane");
constexpr int kXyzLanes = 0x7;  // movemask bits of lanes 0-2

// (p[0], p[1], p[2], 0): never reads p[3], which may lie past the array.
inline __m128 load3(const float* p) {
  const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(p));
  return _mm_movelh_ps(xy, _mm_load_ss(p + 2));
}

// Lane k of v in every lane (pshufd: no copy of v first).
template <int k>
inline __m128 broadcast(__m128 v) {
  return _mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(v), _MM_SHUFFLE(k, k, k, k)));
}

// R^T e, lane i holding r0 e0 + (r1 e1 + r2 e2) of row i (Eigen's sum).
inline __m128 frame_rows(const FrameChange& f, __m128 e) {
  const __m128 a0 = _mm_mul_ps(_mm_load_ps(f.col[0]), broadcast<0>(e));
  const __m128 a1 = _mm_mul_ps(_mm_load_ps(f.col[1]), broadcast<1>(e));
  const __m128 a2 = _mm_mul_ps(_mm_load_ps(f.col[2]), broadcast<2>(e));
  return _mm_add_ps(a0, _mm_add_ps(a1, a2));
}

// x and n: four floats each (lane 3 written).
inline void to_model_frame(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  _mm_storeu_ps(x, frame_rows(f, _mm_sub_ps(load3(q), _mm_load_ps(f.t))));
  _mm_storeu_ps(n, frame_rows(f, load3(qn)));
}

// x: four floats (lane 3 ignored); v: four slots (lane 3 written).
inline bool field_voxel(const FieldBox& b, const float* x, uint32_t* v) {
  const __m128 t = _mm_div_ps(_mm_sub_ps(_mm_loadu_ps(x), _mm_load_ps(b.lo)), _mm_set1_ps(b.cell));
  const __m128 inside = _mm_and_ps(_mm_cmpge_ps(t, _mm_setzero_ps()), _mm_cmplt_ps(t, _mm_load_ps(b.dims)));
  if ((_mm_movemask_ps(inside) & kXyzLanes) != kXyzLanes) return false;
  _mm_storeu_si128(reinterpret_cast<__m128i*>(v), _mm_cvttps_epi32(t));
  return true;
}

}  // namespace sse2
}  // namespace kernels
}  // namespace spinhash
#endif  // __SSE2__ && !__FMA__
