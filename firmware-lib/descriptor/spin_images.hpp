// The spin images of a cloud's basis points, cell by cell: each grid cell's
// neighbourhood is gathered once (CellGrid::gather_neighbourhood) for all
// the basis points in it, and each image is accumulated over it by the
// spin kernel (kernels/spin_select.hpp). The images are those of
// compute_spin_image bit for bit: the same neighbours, in the same order,
// through the same arithmetic.
#pragma once
#include <cstdint>

#include "descriptor/spin_image.hpp"
#include "geometry/cell_grid.hpp"

namespace spinhash {

// Room for gathered neighbourhoods: capacity points' coordinates and
// normals, and each cloud point's place in the basis. None (capacity
// 0), or no SIMD spin kernel built: every image walks the grid
// (compute_spin_image).
struct SpinScratch {
  uint32_t* basis_of = nullptr;  // one per cloud point
  float* x = nullptr;            // capacity each
  float* y = nullptr;
  float* z = nullptr;
  float* nx = nullptr;
  float* ny = nullptr;
  float* nz = nullptr;
  uint32_t capacity = 0;
};

// The images of points[basis[k]] (normal normals[3 basis[k]..]) into
// images + k * dims, k < nb, over the grid built on points[0, n).
void compute_spin_images(const SpinImageParams& sp, const CellGrid& grid, const float* points, uint32_t n,
                         const float* normals, const uint8_t* has_normal, const uint32_t* basis, uint32_t nb,
                         const SpinScratch& scratch, float* images);

// One image over a gathered neighbourhood (zeroed, accumulated by the
// selected kernel, normalised).
void compute_spin_image_gathered(const kernels::SpinGeometry& b, uint32_t dims,
                                 const kernels::SpinNeighbours& g, const float* p, const float* n,
                                 float* image);

}  // namespace spinhash
