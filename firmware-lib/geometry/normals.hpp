// Surface normals by PCA over a radius neighbourhood, and their orientation.
#pragma once
#include <cstdint>

#include "geometry/cell_grid.hpp"

namespace spinhash {

// Smallest middle/largest eigenvalue ratio for a neighbourhood to count as a
// surface: below it the points are (nearly) collinear and have no normal.
constexpr float kMinPlanarRatio = 1e-3f;

// normals[3i..] of every points[i] with >= kMinNormalNeighbours neighbours within
// `radius` (grid built over `points`); has_normal[i] says which. Returns the count.
uint32_t estimate_normals(const CellGrid& grid, const float* points, uint32_t n, float radius, float* normals,
                          uint8_t* has_normal);

// Turns every normal to point away from `centre` (outward for a closed or
// partial object), or towards `viewpoint` when given (sensor position).
void orient_normals(const float* points, uint32_t n, const float* reference, bool is_viewpoint,
                    float* normals, const uint8_t* has_normal);

}  // namespace spinhash
