// The portable reference of the nearest-feature kernels (scalar, and for
// the frame change Eigen's product, the core's arithmetic before them): the
// definition every optimised kernel must reproduce bit for bit
// (tests/core/test_nearest_kernels.cpp), and the kernel of targets without
// one (bare-metal Cortex-M, armhf, SPINHASH_KERNELS_REFERENCE).
#pragma once
#include <Eigen/Core>
#include <cstdint>

#include "kernels/nearest_geometry.hpp"

namespace spinhash {
namespace kernels {
namespace reference {

// Query feature (position q, normal qn) in the model frame: x[0..2] and
// n[0..2] (lane 3 of each is the kernel's to use). Eigen's product, as
// query_in_model_frame computes it on this target.
inline void to_model_frame(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  const Eigen::Map<const Eigen::Matrix3f, 0, Eigen::OuterStride<4>> rt(f.col[0]);
  const Eigen::Vector3f qp(q[0], q[1], q[2]), t(f.t[0], f.t[1], f.t[2]), qv(qn[0], qn[1], qn[2]);
  const Eigen::Vector3f xv = rt * (qp - t), nv = rt * qv;
  for (int i = 0; i < 3; ++i) x[i] = xv[i], n[i] = nv[i];
}

// The field voxel holding x[0..2]: true and v[0..2] set when x lies inside
// the box; false outside (also for inf or NaN coordinates). The index is
// floor(t), taken without floor: floor(t) >= 0 exactly when t >= 0,
// floor(t) < dims exactly when t < dims (an integer), and for t >= 0 the
// conversion truncates to floor(t).
inline bool field_voxel(const FieldBox& b, const float* x, uint32_t* v) {
  for (int a = 0; a < 3; ++a) {
    const float t = field_coordinate(b, a, x[a]);
    if (!(t >= 0.0f && t < b.dims[a])) return false;
    v[a] = static_cast<uint32_t>(t);
  }
  return true;
}

}  // namespace reference
}  // namespace kernels
}  // namespace spinhash
