// What every nearest-feature kernel shares (match/likelihood.cpp's
// verification): a pose's change of frame for query features, the box of a
// model's nearest-feature field, and the scalar arithmetic each SIMD lane
// repeats operation for operation (the core is built with -ffp-contract=off:
// no fused multiply-add), so that every kernel's answers are the
// reference's bit for bit.
#pragma once
#include <cstdint>

namespace spinhash {
namespace kernels {

// A pose's change of frame for query features: x = R^T (q - t), n = R^T qn.
// col[k][i] is R^T(i, k), i.e. R(k, i): column k of R^T, one row per lane.
// Lane 3 of each is zero. Aligned for the SIMD kernels' loads.
struct alignas(16) FrameChange {
  float col[3][4];
  float t[4];
};

// Row i of R^T times e, summed as Eigen's 3x3 product sums it (the golden
// vectors were recorded with it): r0 e0 + (r1 e1 + r2 e2).
inline float frame_row(const FrameChange& f, int i, float e0, float e1, float e2) {
  return f.col[0][i] * e0 + (f.col[1][i] * e1 + f.col[2][i] * e2);
}

// A model's nearest-feature field as a box of voxels (blob_format.hpp):
// its low corner (the grid origin less the field's reach), its voxels per
// axis as floats, and the voxel edge. Lane 3: corner 0, one voxel, so that
// a SIMD lane 3 never fails the box test.
struct alignas(16) FieldBox {
  float lo[4];
  float dims[4];
  float cell;
};

// Axis a's voxel coordinate of x: floor((x - lo) / cell) when inside.
inline float field_coordinate(const FieldBox& b, int a, float x) { return (x - b.lo[a]) / b.cell; }

}  // namespace kernels
}  // namespace spinhash
