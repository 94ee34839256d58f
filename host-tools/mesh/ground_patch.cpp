// Ground around a vehicle, for scans that must also leave ground points.
#include "mesh/seeded_random.hpp"
#include "mesh/vehicle_generator.hpp"

#include <algorithm>
#include <cmath>

namespace spinhash::host {
namespace {

constexpr double kGroundCellSize = 0.5;    // m: fine enough for small bumps
constexpr uint32_t kMaxGroundCells = 400;  // per side: bounds memory for huge patches
constexpr uint64_t kGroundStream = 0x6000;

}  // namespace

Mesh make_ground_patch(double half_size, double z, double bump_height, uint64_t seed) {
  Mesh ground;
  ground.name = "ground";
  if (!(half_size > 0.0) || !std::isfinite(half_size) || !std::isfinite(z) || !std::isfinite(bump_height)) {
    return ground;
  }
  const double cells_wanted = std::ceil(2.0 * half_size / kGroundCellSize);
  const auto cells = static_cast<uint32_t>(std::clamp(cells_wanted, 1.0, double(kMaxGroundCells)));
  const double step = 2.0 * half_size / cells;
  SeededRandom rng(mix_seed(seed, kGroundStream));
  for (uint32_t j = 0; j <= cells; ++j) {
    for (uint32_t i = 0; i <= cells; ++i) {
      const double bump = bump_height > 0.0 ? rng.uniform(-bump_height, bump_height) : 0.0;
      ground.add_vertex({-half_size + i * step, -half_size + j * step, z + bump});
    }
  }
  const uint32_t row = cells + 1;
  for (uint32_t j = 0; j < cells; ++j) {
    for (uint32_t i = 0; i < cells; ++i) {
      const uint32_t a = j * row + i;
      // Counter-clockwise from above: normals point up.
      ground.add_triangle(a, a + 1, a + row + 1);
      ground.add_triangle(a, a + row + 1, a + row);
    }
  }
  return ground;
}

}  // namespace spinhash::host
