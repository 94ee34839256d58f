// The sensor model shared by the single-object simulator (scan_simulator)
// and the tile simulator (scene_simulator): a view looks along a direction;
// its rays form a regular angular grid about it; each hit is moved along its
// ray by Gaussian range noise.
#pragma once

#include "mesh/seeded_random.hpp"
#include "scan/ray_caster.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// One view: sensor position and the orthonormal frame it looks along.
struct View {
  Eigen::Vector3d origin;
  Eigen::Vector3d forward;
  Eigen::Vector3d right;
  Eigen::Vector3d up;
};

// A sensor `distance` from the origin at `azimuth` and `elevation`
// (radians), looking at the origin.
View make_view(double azimuth, double elevation, double distance);

// Square angular grid: `side` x `side` rays `step` radians apart, centred on
// the view direction, reaching `half_angle` off it.
struct RayGrid {
  double half_angle = 0.0;
  double step = 0.0;
  uint64_t side = 0;
  uint64_t rays() const { return side * side; }
};

// Plans the grid covering +-half_angle at `step`; false with *error when
// one view would cast more than kMaxRaysPerView rays, or `views` such views
// more than kMaxRaysPerScan (scan_simulator.hpp), so a bad option cannot
// exhaust memory or time.
bool plan_ray_grid(double half_angle, double step, uint32_t views, RayGrid* grid, std::string* error);

// Casts one view row by row (bounded memory) and appends each hit's point,
// moved along its ray by noise_sigma * N(0, 1) from *noise, to *xyz and the
// geometry it hit (RayCaster::add_mesh order) to *geometry. Returns the hits
// appended, or -1 with *error.
int64_t cast_view(const RayCaster& caster, const View& view, const RayGrid& grid, double noise_sigma,
                  SeededRandom* noise, std::vector<double>* xyz, std::vector<int32_t>* geometry,
                  std::string* error);

}  // namespace spinhash::host
