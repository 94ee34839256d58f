// The shared wheel helpers, and fleet assembly.
#include "mesh/vehicle_generator.hpp"

#include "mesh/vehicle_builders.hpp"
#include "mesh/vehicle_parts.hpp"

#include <algorithm>

namespace spinhash::host {
namespace vehicle {

void add_wheel_pairs(Mesh* mesh, const VehicleSpec& spec, const std::vector<double>& axle_x, double inset) {
  const double y = 0.5 * spec.width - 0.5 * spec.wheel_width - inset;
  for (double x : axle_x) {
    for (double side : {-1.0, 1.0}) {
      add_cylinder(mesh, {x, side * y, spec.wheel_radius}, Axis::kY, spec.wheel_radius, spec.wheel_width,
                   kWheelSegments);
    }
  }
}

std::vector<double> axle_group(double center_x, uint32_t count, double spacing) {
  std::vector<double> xs;
  for (uint32_t i = 0; i < count; ++i) {
    xs.push_back(center_x + (i - 0.5 * (count - 1.0)) * spacing);
  }
  return xs;
}

}  // namespace vehicle

Mesh build_vehicle(const VehicleSpec& spec) {
  Mesh mesh;
  mesh.name = spec.name;
  switch (spec.family) {
    case Family::kSedan: vehicle::build_sedan(spec, &mesh); break;
    case Family::kVan:
    case Family::kSuv: vehicle::build_two_box(spec, &mesh); break;
    case Family::kTruck: vehicle::build_truck(spec, &mesh); break;
    case Family::kTracked: vehicle::build_tracked(spec, &mesh); break;
    case Family::kPickup: vehicle::build_pickup(spec, &mesh); break;
    case Family::kBus: vehicle::build_bus(spec, &mesh); break;
    case Family::kApc: vehicle::build_apc(spec, &mesh); break;
  }
  return mesh;
}

Mesh generate_vehicle(Family family, uint32_t index, uint64_t seed) {
  return build_vehicle(make_vehicle_spec(family, index, seed));
}

std::vector<VehicleSpec> fleet_specs(uint32_t count, uint64_t seed) {
  count = std::min(count, kMaxFleetSize);
  std::vector<VehicleSpec> specs;
  specs.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    specs.push_back(make_vehicle_spec(static_cast<Family>(i % kFamilyCount), i / kFamilyCount, seed));
  }
  return specs;
}

std::vector<Mesh> generate_fleet(uint32_t count, uint64_t seed) {
  std::vector<Mesh> fleet;
  for (const VehicleSpec& spec : fleet_specs(count, seed)) fleet.push_back(build_vehicle(spec));
  return fleet;
}

}  // namespace spinhash::host
