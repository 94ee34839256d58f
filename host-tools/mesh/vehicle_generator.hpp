// Procedural vehicle meshes: families of look-alikes (sedans, vans, trucks,
// tracked vehicles, pickups, buses, wheeled APCs) whose members are similar
// but distinct at the 10-30 cm scale, the hard case for recognition.
//
// Frame: metres, x forward, y left, z up, ground at z = 0, centred on x and
// y. Everything is deterministic from (family, index, seed): the random
// numbers come from std::mt19937_64 bits (see seeded_random.hpp), so a
// fleet is identical on every platform and standard library.
#pragma once

#include "mesh/mesh.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

enum class Family : uint32_t { kSedan, kVan, kTruck, kTracked, kPickup, kBus, kApc };
constexpr uint32_t kFamilyCount = 7;
// Upper bound on generate_fleet's count, so a bad argument cannot exhaust memory.
constexpr uint32_t kMaxFleetSize = 100000;

// "sedan", "van", "truck", "tracked", "pickup", "bus", "apc".
const char* family_name(Family family);
// Parses a family name; false if unknown.
bool parse_family(const std::string& name, Family* family);

// Everything that makes one vehicle: the generator draws it, the builder
// turns it into triangles. Lengths in metres. Fields a family does not use
// keep their defaults.
struct VehicleSpec {
  Family family = Family::kSedan;
  uint32_t index = 0;
  std::string name;  // family-index, e.g. "sedan-03"

  double length = 4.5;             // bumper to bumper (hull for tracked)
  double width = 1.8;              // body width
  double height = 1.45;            // roof (or turret top) above ground
  double ground_clearance = 0.16;  // hull underside above ground
  double belt_height = 0.85;       // top of the lower body (bonnet level)

  double front_length = 1.2;     // bonnet, truck cab, or glacis run
  double rear_length = 0.9;      // boot, pickup/truck bed or cargo box
  double cabin_length = 2.0;     // pickup cab; truck cargo box height uses rear_height
  double windscreen_run = 0.7;   // horizontal run of the sloped windscreen
  double rear_window_run = 0.5;  // horizontal run of the rear window
  double tumblehome = 0.15;      // roof narrower than the body, per side
  double rear_height = 2.6;      // truck cargo box top / tracked engine deck

  double wheel_radius = 0.31;
  double wheel_width = 0.21;
  uint32_t axles = 2;         // 0 for tracked vehicles
  double axle_spacing = 2.7;  // wheelbase (2 axles) or spacing of adjacent axles
  double axle_shift = 0.0;    // wheel set offset along x from the centre
  double track_width = 0.55;  // tracked: width of each track

  bool hatchback = false;
  bool roof_rack = false;
  bool spoiler = false;
  bool spare_wheel = false;
  bool flatbed = false;    // truck: flatbed instead of a cargo box
  bool bed_cover = false;  // pickup: closed tonneau cover
  bool turret = false;
  bool barrel = false;
  double turret_x = 0.0;  // turret centre along x
  double turret_length = 2.6;
  double turret_width = 2.2;
  double turret_height = 0.75;
  double barrel_length = 4.0;
};

// Draws the spec of member `index` of a family. Lengths are spread over the
// family's range by a low-discrepancy sequence, so members differ.
VehicleSpec make_vehicle_spec(Family family, uint32_t index, uint64_t seed);
// Builds the closed, outward-wound surface of a spec; name = spec.name.
Mesh build_vehicle(const VehicleSpec& spec);
Mesh generate_vehicle(Family family, uint32_t index, uint64_t seed);

// Member i of the fleet is family i % kFamilyCount, index i / kFamilyCount,
// so any count >= 4 holds sedans, vans, trucks and tracked vehicles, and
// names are unique. count is clamped to kMaxFleetSize.
std::vector<VehicleSpec> fleet_specs(uint32_t count, uint64_t seed);
std::vector<Mesh> generate_fleet(uint32_t count, uint64_t seed);

// Flat square ground of side 2*half_size at height z (normal up), meshed on
// a grid; with bump_height > 0 every grid vertex is raised or lowered by up
// to that much (deterministic from seed). A bad size gives an empty mesh.
Mesh make_ground_patch(double half_size, double z, double bump_height = 0.0, uint64_t seed = 0);

}  // namespace spinhash::host
