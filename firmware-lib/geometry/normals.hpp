// Surface normals by PCA over a radius neighbourhood, and their orientation.
#pragma once
#include <cstdint>

#include "geometry/cell_grid.hpp"

namespace spinhash {

// Smallest middle/largest eigenvalue ratio for a neighbourhood to count as a
// surface: below it the points are (nearly) collinear and have no normal.
constexpr float kMinPlanarRatio = 1e-3f;

// Room for a gathered neighbourhood (CellGrid::gather_neighbourhood):
// capacity points' coordinates. None: every point searches the grid.
struct NeighbourScratch {
  float* x = nullptr;  // capacity each
  float* y = nullptr;
  float* z = nullptr;
  uint32_t capacity = 0;
};

// normals[3i..] of every points[i] with >= kMinNormalNeighbours neighbours within
// `radius` (grid built over `points`, all n of them); has_normal[i] says
// which. Returns the count. With scratch, the neighbourhood of each grid
// cell is gathered once for all its points: the same normals, bit for bit
// (the same points in the same order), without a cell lookup per point.
uint32_t estimate_normals(const CellGrid& grid, const float* points, uint32_t n, float radius, float* normals,
                          uint8_t* has_normal, const NeighbourScratch& scratch = NeighbourScratch{});

// Without a viewpoint, z is up and the sensor above: an airborne scan, or
// the database's model scans from 45 degrees elevation. A surface within 45
// degrees of level is then seen from above, whatever its place: its normal
// faces up. Steeper ones face away from the vertical line through `centre`
// (the cloud's centroid). Turning every normal away from the centroid
// itself turned a car's hood and trunk, or a pickup's bed, downward when
// they lay below the centroid of an airborne scan (which shows more roof
// than the model's all-round scan does), while the model kept them up: the
// spin images of those features no longer matched their model's.
constexpr float kFacesUpZ = 0.70710678f;  // cos 45 degrees
// Turns every normal as above, or towards `viewpoint` when given (the sensor
// position).
void orient_normals(const float* points, uint32_t n, const float* reference, bool is_viewpoint,
                    float* normals, const uint8_t* has_normal);

}  // namespace spinhash
