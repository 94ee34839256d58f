#include "kernels/nearest_entry.hpp"

#include "match/likelihood.hpp"

namespace spinhash {
namespace kernels {

void to_model_frame_reference(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  reference::to_model_frame(f, q, qn, x, n);
}
bool field_voxel_reference(const FieldBox& b, const float* x, uint32_t* v) {
  return reference::field_voxel(b, x, v);
}
#if defined(SPINHASH_KERNELS_HAVE_SSE2_NEAREST)
void to_model_frame_sse2(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  sse2::to_model_frame(f, q, qn, x, n);
}
bool field_voxel_sse2(const FieldBox& b, const float* x, uint32_t* v) { return sse2::field_voxel(b, x, v); }
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_NEAREST)
void to_model_frame_neon(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  neon::to_model_frame(f, q, qn, x, n);
}
bool field_voxel_neon(const FieldBox& b, const float* x, uint32_t* v) { return neon::field_voxel(b, x, v); }
#endif
void to_model_frame_selected(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  to_model_frame(f, q, qn, x, n);
}
bool field_voxel_selected(const FieldBox& b, const float* x, uint32_t* v) { return field_voxel(b, x, v); }

void to_model_frame_eigen(const FrameChange& f, const float* q, const float* qn, float* x, float* n) {
  Eigen::Matrix3f rt;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) rt(i, k) = f.col[k][i];
  QueryFeatures one;
  one.positions = q;
  one.normals = qn;
  one.count = 1;
  Eigen::Vector3f ex, en;
  query_in_model_frame(one, 0, rt, Eigen::Vector3f(f.t[0], f.t[1], f.t[2]), &ex, &en);
  for (int i = 0; i < 3; ++i) x[i] = ex[i], n[i] = en[i];
}

}  // namespace kernels
}  // namespace spinhash
