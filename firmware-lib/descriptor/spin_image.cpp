#include "descriptor/spin_image.hpp"

#include <cmath>

#include "util/angle_math.hpp"

namespace spinhash {

namespace {

// The bin geometry of one image, worked out once per image rather than per
// vote (a spin image takes a few hundred votes).
struct SpinBins {
  float bin_a, bin_b;    // bin widths along alpha and beta
  float last_a, last_b;  // the last bin centre's index, as a float
  uint32_t bins_alpha, bins_beta;
  float radius;
};

SpinBins spin_bins(const SpinImageParams& sp) {
  SpinBins b;
  b.bin_a = sp.radius / static_cast<float>(sp.bins_alpha);
  b.bin_b = 2.0f * sp.radius / static_cast<float>(sp.bins_beta);
  b.last_a = static_cast<float>(sp.bins_alpha - 1u);
  b.last_b = static_cast<float>(sp.bins_beta - 1u);
  b.bins_alpha = sp.bins_alpha;
  b.bins_beta = sp.bins_beta;
  b.radius = sp.radius;
  return b;
}

inline void vote(const SpinBins& b, float alpha, float beta, float* image) {
  // Continuous bin coordinates with bin centres at integers.
  float fa = clampf(alpha / b.bin_a - 0.5f, 0.0f, b.last_a);
  float fb = clampf((beta + b.radius) / b.bin_b - 0.5f, 0.0f, b.last_b);
  uint32_t i0 = static_cast<uint32_t>(fa), j0 = static_cast<uint32_t>(fb);
  uint32_t i1 = i0 + 1u < b.bins_alpha ? i0 + 1u : i0;
  uint32_t j1 = j0 + 1u < b.bins_beta ? j0 + 1u : j0;
  float wa = fa - static_cast<float>(i0), wb = fb - static_cast<float>(j0);
  image[j0 * b.bins_alpha + i0] += (1.0f - wa) * (1.0f - wb);
  image[j0 * b.bins_alpha + i1] += wa * (1.0f - wb);
  image[j1 * b.bins_alpha + i0] += (1.0f - wa) * wb;
  image[j1 * b.bins_alpha + i1] += wa * wb;
}

}  // namespace

void spin_vote(const SpinImageParams& sp, float alpha, float beta, float* image) {
  vote(spin_bins(sp), alpha, beta, image);
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
  const SpinBins bins = spin_bins(sp);
  for (uint32_t i = 0; i < dims; ++i) image[i] = 0.0f;
  grid.for_each_within(p, sp.radius, [&](uint32_t j) {
    if (sp.use_support_angle) {
      // Self-occlusion and clutter mostly come from surfaces facing away.
      const float* nj = normals + 3u * j;
      if (!has_normal[j] || n[0] * nj[0] + n[1] * nj[1] + n[2] * nj[2] < sp.cos_support_angle) return;
    }
    const float* x = points + 3u * j;
    float dx = x[0] - p[0], dy = x[1] - p[1], dz = x[2] - p[2];
    float beta = n[0] * dx + n[1] * dy + n[2] * dz;
    float alpha2 = dx * dx + dy * dy + dz * dz - beta * beta;
    vote(bins, std::sqrt(alpha2 > 0.0f ? alpha2 : 0.0f), beta, image);
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
