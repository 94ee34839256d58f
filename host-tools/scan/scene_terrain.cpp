#include "scan/scene_terrain.hpp"

#include "mesh/seeded_random.hpp"
#include "util/angles.hpp"

#include <algorithm>
#include <cmath>

namespace spinhash::host {
namespace {

constexpr uint64_t kTerrainStream = 0x7100;
constexpr double kBumpSigmaMin = 2.0, kBumpSigmaMax = 5.0;  // m: smooth under a vehicle
constexpr double kCurbRamp = 0.1;                           // m over which the curb rises

}  // namespace

TerrainSpec level_ground() {
  TerrainSpec flat;
  flat.slope_deg = 0.0;
  flat.bump_height = 0.0;
  flat.curb_height = 0.0;
  return flat;
}

Terrain::Terrain(const TerrainSpec& spec) : spec_(spec) {
  SeededRandom rng(mix_seed(spec.seed, kTerrainStream));
  const double drawn = rng.uniform(0.0, 2.0 * kPi);
  const double azimuth = spec.slope_azimuth_deg >= 0.0 ? spec.slope_azimuth_deg * kDegToRad : drawn;
  const double rise = std::tan(spec.slope_deg * kDegToRad);
  gradient_ = rise * Eigen::Vector2d(std::cos(azimuth), std::sin(azimuth));
  const double half = 0.5 * spec.size;
  for (uint32_t k = 0; k < kTerrainBumps; ++k) {
    bump_x_[k] = rng.uniform(-half, half);
    bump_y_[k] = rng.uniform(-half, half);
    bump_a_[k] = rng.uniform(-spec.bump_height, spec.bump_height);
    bump_s_[k] = rng.uniform(kBumpSigmaMin, kBumpSigmaMax);
  }
  // The curb crosses the tile's middle half.
  curb_point_ = {rng.uniform(-0.25 * half, 0.25 * half), rng.uniform(-0.25 * half, 0.25 * half)};
  const double curb_dir = rng.uniform(0.0, 2.0 * kPi);
  curb_normal_ = {std::cos(curb_dir), std::sin(curb_dir)};
}

double Terrain::curb_distance(double x, double y) const {
  return (Eigen::Vector2d(x, y) - curb_point_).dot(curb_normal_);
}

double Terrain::height(double x, double y) const {
  double z = gradient_.x() * x + gradient_.y() * y;
  for (uint32_t k = 0; k < kTerrainBumps; ++k) {
    const double dx = x - bump_x_[k], dy = y - bump_y_[k];
    z += bump_a_[k] * std::exp(-(dx * dx + dy * dy) / (2.0 * bump_s_[k] * bump_s_[k]));
  }
  const double t = std::clamp(curb_distance(x, y) / kCurbRamp + 0.5, 0.0, 1.0);
  return z + spec_.curb_height * t * t * (3.0 - 2.0 * t);  // smoothstep
}

Eigen::Vector3d Terrain::plane_normal() const {
  return Eigen::Vector3d(-gradient_.x(), -gradient_.y(), 1.0).normalized();
}

Mesh Terrain::mesh() const {
  Mesh m;
  m.name = "terrain";
  const double cells_wanted = std::ceil(spec_.size / kTerrainCell);
  const auto cells = static_cast<uint32_t>(std::clamp(cells_wanted, 1.0, double(kMaxTerrainCells)));
  const double step = spec_.size / cells, half = 0.5 * spec_.size;
  for (uint32_t j = 0; j <= cells; ++j) {
    for (uint32_t i = 0; i <= cells; ++i) {
      const double x = -half + i * step, y = -half + j * step;
      m.add_vertex({x, y, height(x, y)});
    }
  }
  const uint32_t row = cells + 1;
  for (uint32_t j = 0; j < cells; ++j) {
    for (uint32_t i = 0; i < cells; ++i) {
      const uint32_t a = j * row + i;
      m.add_triangle(a, a + 1, a + row + 1);  // counter-clockwise from above: normals up
      m.add_triangle(a, a + row + 1, a + row);
    }
  }
  return m;
}

}  // namespace spinhash::host
