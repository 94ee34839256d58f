// The tile simulator's terrain: a height field z = h(x, y) over a square
// tile centred on the origin: a plane of the given slope in a random
// direction, smooth Gaussian bumps and one straight curb step, all bounded
// and drawn from a seed.
#pragma once

#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstdint>

namespace spinhash::host {

constexpr uint32_t kTerrainBumps = 4;
constexpr double kTerrainCell = 0.2;         // m: mesh grid step (keeps bumps and the curb smooth)
constexpr uint32_t kMaxTerrainCells = 2000;  // per side: bounds the mesh for huge tiles

struct TerrainSpec {
  double size = 40.0;               // m, tile side
  double slope_deg = 0.0;           // of the plane
  double slope_azimuth_deg = -1.0;  // direction it rises to, degrees from +x (< 0: drawn from the seed)
  double bump_height = 0.3;         // m, largest |amplitude| of a bump
  double curb_height = 0.15;        // m, the step's rise
  uint64_t seed = 1;
};

// Level ground: no slope, no bumps, no curb (an object scanned on its own).
TerrainSpec level_ground();

class Terrain {
 public:
  explicit Terrain(const TerrainSpec& spec);
  const TerrainSpec& spec() const { return spec_; }
  // Height of the analytic surface (the mesh interpolates it between grid nodes).
  double height(double x, double y) const;
  // Unit normal of the plane alone (no bumps, no curb).
  Eigen::Vector3d plane_normal() const;
  // Signed distance (m) from the curb line; the curb rises where it is > 0.
  double curb_distance(double x, double y) const;
  // The height field as a mesh, normals up.
  Mesh mesh() const;

 private:
  TerrainSpec spec_;
  Eigen::Vector2d gradient_;  // of the plane
  Eigen::Vector2d curb_point_, curb_normal_;
  double bump_x_[kTerrainBumps], bump_y_[kTerrainBumps], bump_a_[kTerrainBumps], bump_s_[kTerrainBumps];
};

}  // namespace spinhash::host
