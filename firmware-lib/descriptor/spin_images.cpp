#include "descriptor/spin_images.hpp"

#include <limits>

#include "kernels/spin_select.hpp"

namespace spinhash {
namespace {

constexpr uint32_t kNotBasis = 0xFFFFFFFFu;
// Not yet gathered: the cell holds no basis point before it.
constexpr uint32_t kNotGathered = 0xFFFFFFFEu;
static_assert(CellGrid::kGatherOverflow != kNotGathered, "distinct sentinels");

// The coordinates and normals of the points CellGrid::for_each_cell_near
// visits around cell c, in its order, into s's arrays (NaN normals where a
// point has none: the kernels' support test rejects it, as the grid walk
// does). Returns how many, or kGatherOverflow when more than s.capacity
// (nothing usable).
uint32_t gather_oriented(const SpinScratch& s, const CellGrid& grid, uint32_t c, int32_t reach,
                         const float* points, const float* normals, const uint8_t* has_normal) {
  const float none = std::numeric_limits<float>::quiet_NaN();
  const float no_normal[3] = {none, none, none};
  uint32_t count = 0;
  grid.for_each_cell_near(c, reach, [&](const uint32_t* it, uint32_t size) {
    if (size > s.capacity - count) {
      count = CellGrid::kGatherOverflow;
      return false;
    }
    // Coordinates, then normals: each loop keeps its few pointers in registers.
    float *x = s.x + count, *y = s.y + count, *z = s.z + count;
    for (uint32_t k = 0; k < size; ++k) {
      const float* p = points + 3u * it[k];
      x[k] = p[0], y[k] = p[1], z[k] = p[2];
    }
    float *nx = s.nx + count, *ny = s.ny + count, *nz = s.nz + count;
    for (uint32_t k = 0; k < size; ++k) {
      const float* n = has_normal[it[k]] != 0u ? normals + 3u * it[k] : no_normal;
      nx[k] = n[0], ny[k] = n[1], nz[k] = n[2];
    }
    count += size;
    return true;
  });
  return count;
}

}  // namespace

void compute_spin_image_gathered(const kernels::SpinGeometry& b, uint32_t dims,
                                 const kernels::SpinNeighbours& g, const float* p, const float* n,
                                 float* image) {
  for (uint32_t i = 0; i < dims; ++i) image[i] = 0.0f;
  kernels::spin_accumulate(b, g, p, n, image);
  normalize_spin(image, dims);
}

void compute_spin_images(const SpinImageParams& sp, const CellGrid& grid, const float* points, uint32_t n,
                         const float* normals, const uint8_t* has_normal, const uint32_t* basis, uint32_t nb,
                         const SpinScratch& scratch, float* images) {
  const uint32_t dims = sp.bins_alpha * sp.bins_beta;
  auto walk = [&](uint32_t k) {
    const uint32_t i = basis[k];
    compute_spin_image(sp, grid, points, normals, has_normal, points + 3u * i, normals + 3u * i,
                       images + static_cast<size_t>(k) * dims);
  };
  // Without a SIMD kernel (kernels::kSpinGathers false) the code below is
  // dead and compiled out: the bare-metal image keeps only the walk.
  if (!kernels::kSpinGathers || scratch.capacity == 0u || grid.cell_count() == 0u) {
    for (uint32_t k = 0; k < nb; ++k) walk(k);
    return;
  }
  for (uint32_t i = 0; i < n; ++i) scratch.basis_of[i] = kNotBasis;
  for (uint32_t k = 0; k < nb; ++k) {
    if (scratch.basis_of[basis[k]] != kNotBasis)
      walk(k);  // a repeated point: its own search
    else
      scratch.basis_of[basis[k]] = k;
  }
  // Cell by cell (every point lies in one, and for_each_within searches
  // from the cell a point lies in): the neighbourhood is gathered when the
  // cell's first basis point is met, then serves all of them; one beyond
  // the scratch's capacity is searched point by point.
  const kernels::SpinGeometry b = spin_geometry(sp);
  const int32_t reach = grid.reach_of(sp.radius);
  const uint32_t* order = grid.order();
  const kernels::SpinNeighbours g{scratch.x, scratch.y, scratch.z, scratch.nx, scratch.ny, scratch.nz, 0u};
  for (uint32_t c = 0; c < grid.cell_count(); ++c) {
    const uint32_t first = grid.cell_first(c), size = grid.cell_size_of(c);
    uint32_t gathered = kNotGathered;
    for (uint32_t t = first; t < first + size; ++t) {
      const uint32_t k = scratch.basis_of[order[t]];
      if (k == kNotBasis) continue;
      if (gathered == kNotGathered)
        gathered =
            sp.use_support_angle
                ? gather_oriented(scratch, grid, c, reach, points, normals, has_normal)
                : grid.gather_neighbourhood(c, reach, scratch.x, scratch.y, scratch.z, scratch.capacity);
      if (gathered == CellGrid::kGatherOverflow) {
        walk(k);
        continue;
      }
      kernels::SpinNeighbours cell = g;
      cell.count = gathered;
      const uint32_t i = basis[k];
      compute_spin_image_gathered(b, dims, cell, points + 3u * i, normals + 3u * i,
                                  images + static_cast<size_t>(k) * dims);
    }
  }
}

}  // namespace spinhash
