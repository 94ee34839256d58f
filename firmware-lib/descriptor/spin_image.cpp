#include "descriptor/spin_image.hpp"

#include <cmath>

#include "kernels/spin_geometry.hpp"

namespace spinhash {

kernels::SpinGeometry spin_geometry(const SpinImageParams& sp) {
  kernels::SpinGeometry b;
  b.bin_a = sp.radius / static_cast<float>(sp.bins_alpha);
  b.bin_b = 2.0f * sp.radius / static_cast<float>(sp.bins_beta);
  b.last_a = static_cast<float>(sp.bins_alpha - 1u);
  b.last_b = static_cast<float>(sp.bins_beta - 1u);
  b.bins_alpha = sp.bins_alpha;
  b.bins_beta = sp.bins_beta;
  b.radius = sp.radius;
  b.r2 = sp.radius * sp.radius;
  b.use_support_angle = sp.use_support_angle;
  b.cos_support_angle = sp.cos_support_angle;
  return b;
}

void spin_vote(const SpinImageParams& sp, float alpha, float beta, float* image) {
  kernels::spin_vote(spin_geometry(sp), alpha, beta, image);
}

void normalize_spin(float* image, uint32_t dims) {
  float sum = 0.0f;
  for (uint32_t i = 0; i < dims; ++i) sum += image[i];
  if (!(sum > 0.0f)) return;
  float inv = 1.0f / sum;
  for (uint32_t i = 0; i < dims; ++i) image[i] *= inv;
}

void compute_spin_image(const SpinImageParams& sp, const CellGrid& grid, const float* points,
                        const float* normals, const uint8_t* has_normal, const float* p, const float* n,
                        float* image) {
  const uint32_t dims = sp.bins_alpha * sp.bins_beta;
  const kernels::SpinGeometry bins = spin_geometry(sp);
  for (uint32_t i = 0; i < dims; ++i) image[i] = 0.0f;
  grid.for_each_within(p, sp.radius, [&](uint32_t j) {
    if (sp.use_support_angle) {
      // Self-occlusion and clutter mostly come from surfaces facing away.
      const float* nj = normals + 3u * j;
      if (!has_normal[j] || n[0] * nj[0] + n[1] * nj[1] + n[2] * nj[2] < sp.cos_support_angle) return;
    }
    const float* x = points + 3u * j;
    kernels::spin_vote_offset(bins, n, x[0] - p[0], x[1] - p[1], x[2] - p[2], image);
  });
  normalize_spin(image, dims);
}

void quantize_spin(const float* image, uint32_t dims, float scale, uint8_t* out) {
  for (uint32_t i = 0; i < dims; ++i) {
    float q = image[i] * scale + 0.5f;
    out[i] = q >= 255.0f ? 255u : (q > 0.0f ? static_cast<uint8_t>(q) : 0u);
  }
}

}  // namespace spinhash
