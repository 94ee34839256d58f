// Every nearest-feature kernel this build holds, out of line and compiled
// with the core's flags (-ffp-contract=off), for the kernel tests
// (tests/core/test_nearest_kernels.cpp). The core itself inlines the
// selected one.
#pragma once
#include "kernels/nearest_select.hpp"

namespace spinhash {
namespace kernels {

using ToModelFrame = void (*)(const FrameChange&, const float*, const float*, float*, float*);
using FieldVoxel = bool (*)(const FieldBox&, const float*, uint32_t*);

void to_model_frame_reference(const FrameChange& f, const float* q, const float* qn, float* x, float* n);
bool field_voxel_reference(const FieldBox& b, const float* x, uint32_t* v);
#if defined(SPINHASH_KERNELS_HAVE_SSE2_NEAREST)
void to_model_frame_sse2(const FrameChange& f, const float* q, const float* qn, float* x, float* n);
bool field_voxel_sse2(const FieldBox& b, const float* x, uint32_t* v);
#endif
#if defined(SPINHASH_KERNELS_HAVE_NEON_NEAREST)
void to_model_frame_neon(const FrameChange& f, const float* q, const float* qn, float* x, float* n);
bool field_voxel_neon(const FieldBox& b, const float* x, uint32_t* v);
#endif
void to_model_frame_selected(const FrameChange& f, const float* q, const float* qn, float* x, float* n);
bool field_voxel_selected(const FieldBox& b, const float* x, uint32_t* v);

// The frame change as refinement computes it (match/likelihood.hpp's
// query_in_model_frame, Eigen's product): the kernels must agree with it.
void to_model_frame_eigen(const FrameChange& f, const float* q, const float* qn, float* x, float* n);

}  // namespace kernels
}  // namespace spinhash
