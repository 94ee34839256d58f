// What every spin-image accumulation kernel shares: the geometry of one
// image's votes, the neighbourhood they read (coordinates and normals in
// separate arrays, as CellGrid::gather_neighbourhood lays them out), and the
// scalar arithmetic of one neighbour, which each SIMD lane repeats operation
// for operation (the core is built with -ffp-contract=off: no fused
// multiply-add), so that every kernel's image is the reference's bit for bit.
#pragma once
#include <cmath>
#include <cstdint>

#include "util/angle_math.hpp"

namespace spinhash {
namespace kernels {

// The bin geometry of one image, worked out once per image rather than per
// vote (a spin image takes a few hundred votes).
struct SpinGeometry {
  float bin_a, bin_b;    // bin widths along alpha and beta
  float last_a, last_b;  // the last bin centre's index, as a float
  uint32_t bins_alpha, bins_beta;
  float radius;
  float r2;  // radius * radius: CellGrid::for_each_within's exact test, d2 <= r2
  bool use_support_angle;
  float cos_support_angle;  // neighbours with n . n_x below it are ignored
};

// A gathered neighbourhood: count points' coordinates and normals. A point
// without a normal has NaN ones, which fail the support test (dot >= cos is
// false for NaN) as has_normal == 0 does in the grid walk.
struct SpinNeighbours {
  const float* x;
  const float* y;
  const float* z;
  const float* nx;  // read only with use_support_angle
  const float* ny;
  const float* nz;
  uint32_t count;
};

// Adds a unit vote for a point at (alpha, beta), split bilinearly between the
// four nearest bin centres (votes beyond the outer centres go to the rim bins).
inline void spin_vote(const SpinGeometry& b, float alpha, float beta, float* image) {
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

// The vote of a neighbour at offset (dx, dy, dz) from the oriented point
// (unit normal n) that passed the radius and support tests.
inline void spin_vote_offset(const SpinGeometry& b, const float* n, float dx, float dy, float dz,
                             float* image) {
  float beta = n[0] * dx + n[1] * dy + n[2] * dz;
  float alpha2 = dx * dx + dy * dy + dz * dz - beta * beta;
  spin_vote(b, std::sqrt(alpha2 > 0.0f ? alpha2 : 0.0f), beta, image);
}

// One gathered neighbour k: the grid walk's radius test (the same
// arithmetic as CellGrid::for_each_within), the support test, the vote.
inline void spin_neighbour(const SpinGeometry& b, const SpinNeighbours& g, uint32_t k, const float* p,
                           const float* n, float* image) {
  const float ex = g.x[k] - p[0], ey = g.y[k] - p[1], ez = g.z[k] - p[2];
  if (!(ex * ex + ey * ey + ez * ez <= b.r2)) return;
  if (b.use_support_angle && !(n[0] * g.nx[k] + n[1] * g.ny[k] + n[2] * g.nz[k] >= b.cos_support_angle))
    return;
  spin_vote_offset(b, n, ex, ey, ez, image);
}

}  // namespace kernels
}  // namespace spinhash
