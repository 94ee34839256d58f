// What every nearest-feature kernel shares (match/likelihood.cpp's
// verification): a pose's change of frame for query features and the box
// of a model's nearest-feature field. The frame change is defined as
// Eigen's 3x3 product, as verification and refinement computed it before
// the kernels (query_in_model_frame); its rounding depends on the target
// (on aarch64 Eigen's NEON product fuses rows 0-1 with vfma), and each SIMD
// kernel reproduces its target's, so that answers do not move on any.
#pragma once
#include <cstdint>

namespace spinhash {
namespace kernels {

// A pose's change of frame for query features: x = R^T (q - t), n = R^T qn.
// col[k][i] is R^T(i, k), i.e. R(k, i): column k of R^T, one row per lane
// (R^T column-major with a stride of 4). Lane 3 of each is zero. Aligned
// for the SIMD kernels' loads.
struct alignas(16) FrameChange {
  float col[3][4];
  float t[4];
};

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
