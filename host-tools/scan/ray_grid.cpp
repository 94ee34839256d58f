#include "scan/ray_grid.hpp"

#include "scan/scan_simulator.hpp"

#include <cmath>

namespace spinhash::host {
namespace {

// Below this |forward x up| the view looks straight down: use x for "right".
constexpr double kVerticalViewTolerance = 1e-9;

}  // namespace

View make_view(double azimuth, double elevation, double distance) {
  View v;
  const Eigen::Vector3d out(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                            std::sin(elevation));
  v.origin = distance * out;
  v.forward = -out;
  v.right = v.forward.cross(Eigen::Vector3d::UnitZ());
  if (v.right.norm() < kVerticalViewTolerance) v.right = Eigen::Vector3d::UnitX();
  v.right.normalize();
  v.up = v.right.cross(v.forward);
  return v;
}

bool plan_ray_grid(double half_angle, double step, uint32_t views, RayGrid* grid, std::string* error) {
  if (!(half_angle > 0.0) || !(step > 0.0) || !std::isfinite(half_angle / step)) {
    *error = "ray grid: angles must be positive and finite";
    return false;
  }
  const double per_side = std::floor(2.0 * half_angle / step) + 1.0;
  const double per_view = per_side * per_side;
  if (per_view > double(kMaxRaysPerView) || per_view * views > double(kMaxRaysPerScan)) {
    *error = std::to_string(per_view) + " rays per view, " + std::to_string(per_view * views) +
             " in all (limits: " + std::to_string(kMaxRaysPerView) + " per view, " +
             std::to_string(kMaxRaysPerScan) + " per scan)";
    return false;
  }
  grid->half_angle = half_angle;
  grid->step = step;
  grid->side = static_cast<uint64_t>(per_side);
  return true;
}

int64_t cast_view(const RayCaster& caster, const View& view, const RayGrid& grid, double noise_sigma,
                  SeededRandom* noise, std::vector<double>* xyz, std::vector<int32_t>* geometry,
                  std::string* error) {
  std::vector<Ray> rays(grid.side);
  std::vector<RayHit> hits;
  int64_t kept = 0;
  for (uint64_t j = 0; j < grid.side; ++j) {
    const double b = -grid.half_angle + j * grid.step;
    for (uint64_t i = 0; i < grid.side; ++i) {
      const double a = -grid.half_angle + i * grid.step;
      const Eigen::Vector3d d =
          std::cos(b) * (std::cos(a) * view.forward + std::sin(a) * view.right) + std::sin(b) * view.up;
      rays[i] = {view.origin.cast<float>(), d.cast<float>()};
    }
    if (!caster.cast(rays, &hits, error)) return -1;
    for (uint64_t i = 0; i < grid.side; ++i) {
      if (!hits[i].hit()) continue;
      // The float ray Embree traced, so distance and direction agree.
      const Eigen::Vector3d dir = rays[i].direction.cast<double>();
      const double range = hits[i].distance + noise_sigma * noise->gaussian();
      const Eigen::Vector3d p = rays[i].origin.cast<double>() + range * dir;
      xyz->insert(xyz->end(), {p.x(), p.y(), p.z()});
      geometry->push_back(hits[i].geometry);
      ++kept;
    }
  }
  return kept;
}

}  // namespace spinhash::host
