// Spin images (Johnson & Hebert 1999) with bilinear voting. Layout: bin
// (alpha i, beta j) at index j * bins_alpha + i; alpha in [0, R] (radial
// distance from the normal line), beta in [-R, R] (height along the normal).
#pragma once
#include <cstdint>

#include "geometry/cell_grid.hpp"
#include "kernels/spin_geometry.hpp"
#include "spinhash/internal/spin_quantize.hpp"  // quantize_spin

namespace spinhash {

struct SpinImageParams {
  float radius = 1.0f;  // support radius R
  uint32_t bins_alpha = 10;
  uint32_t bins_beta = 10;
  bool use_support_angle = true;
  float cos_support_angle = 0.5f;  // neighbours with n . n_x below are ignored
};

// The kernels' view of the parameters (bin widths, the search's r2).
kernels::SpinGeometry spin_geometry(const SpinImageParams& sp);

// Adds a unit vote for a point at (alpha, beta), split bilinearly between the
// four nearest bin centres (votes beyond the outer centres go to the rim bins).
void spin_vote(const SpinImageParams& sp, float alpha, float beta, float* image);

// Scales image so its bins sum to 1 (left unchanged when empty).
void normalize_spin(float* image, uint32_t dims);

// Spin image of oriented point (p, n) over points within R found in `grid`.
void compute_spin_image(const SpinImageParams& sp, const CellGrid& grid, const float* points,
                        const float* normals, const uint8_t* has_normal, const float* p, const float* n,
                        float* image);

}  // namespace spinhash
