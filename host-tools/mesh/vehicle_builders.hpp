// Internal to the vehicle generator: one builder per family, and the parts
// the families share. Each builder appends a closed, outward-wound surface.
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/vehicle_generator.hpp"

#include <vector>

namespace spinhash::host::vehicle {

// Tyres: 14-sided cylinders (the brief's 12-16), axis y.
constexpr uint32_t kWheelSegments = 14;

// A pair of wheels (left and right) on each axle position along x, the outer
// face inset from the body side.
void add_wheel_pairs(Mesh* mesh, const VehicleSpec& spec, const std::vector<double>& axle_x, double inset);
// Axle positions evenly spaced by spacing, centred at center_x.
std::vector<double> axle_group(double center_x, uint32_t count, double spacing);

void build_sedan(const VehicleSpec& spec, Mesh* mesh);
// Vans, MPVs and SUVs: a bonnet and one tall cabin to the tail.
void build_two_box(const VehicleSpec& spec, Mesh* mesh);
void build_pickup(const VehicleSpec& spec, Mesh* mesh);
void build_truck(const VehicleSpec& spec, Mesh* mesh);
void build_bus(const VehicleSpec& spec, Mesh* mesh);
void build_tracked(const VehicleSpec& spec, Mesh* mesh);
void build_apc(const VehicleSpec& spec, Mesh* mesh);

}  // namespace spinhash::host::vehicle
