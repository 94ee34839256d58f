// Procedural vehicle meshes: families of look-alikes (saloons and
// hatchbacks, vans and MPVs, lorries, tracked vehicles, pickups, buses,
// wheeled APCs, SUVs) whose members are similar but distinct at the
// 10-30 cm scale, the hard case for recognition. Each family has several
// body styles, and the dimensions of each style are those real vehicles of
// that style span (the table and its sources are in vehicle_specs.cpp), so
// the classes overlap as real ones do.
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

// Family names are class names (vehicle_classes.h), so a generated mesh's
// class follows from its name. Families are only appended: a fleet's member
// i is family i % kFamilyCount.
enum class Family : uint32_t { kSedan, kVan, kTruck, kTracked, kPickup, kBus, kApc, kSuv };
constexpr uint32_t kFamilyCount = 8;

// Body styles within the families (vehicle_specs.cpp gives each its share of
// the family and its real-world dimension ranges).
enum class BodyStyle : uint32_t {
  kHatchback,         // sedan: city car to compact hatchback
  kNotchback,         // sedan: saloon with a separate boot
  kFastback,          // sedan: liftback, long sloping rear window
  kEstate,            // sedan: long roof to an upright tail
  kCoupe,             // sedan: low two-door, long bonnet
  kMpv,               // van: people carrier, car-derived compact van
  kMidVan,            // van: mid-size panel van or minibus, low roof
  kHighRoofVan,       // van: large panel van or minibus, high roof
  kMidPickup,         // pickup: mid-size (single, extra or crew cab)
  kFullPickup,        // pickup: full-size
  kLightTruck,        // truck: light lorry up to 7.5 t, box or dropside
  kRigidTruck,        // truck: medium or heavy rigid, box or flatbed
  kTractorUnit,       // truck: tractor unit without its semi-trailer
  kTipper,            // truck: tipper with an open body
  kMidibus,           // bus: midibus
  kCityBus,           // bus: low-floor city bus
  kCoach,             // bus: coach
  kMainBattleTank,    // tracked: big turret, long gun
  kIfv,               // tracked: infantry fighting vehicle, small turret
  kTrackedCarrier,    // tracked: turretless carrier, box superstructure
  kSelfPropelledGun,  // tracked: big rear turret, very long gun
  kApc8x8,            // apc: four axles
  kApc6x6,            // apc: three axles
  kApc4x4,            // apc: protected patrol vehicle, two axles
  kCrossover,         // suv: crossover, sloping tailgate
  kSuv,               // suv: mid or full-size SUV
  kOffRoader,         // suv: boxy off-roader, spare wheel on the tailgate
};
constexpr uint32_t kBodyStyleCount = 27;

struct DimensionRange {
  double lo;
  double hi;
};
// Members of a family take their styles in a cycle of this many: each
// style holds a fixed number of its slots, its share of the family.
constexpr uint32_t kStyleCycle = 20;
// A body style: its family, its name ("notchback", "high-roof-van", ...),
// its slots of the family's style cycle and the overall length (hull for
// tracked vehicles, gun excluded), width (mirrors excluded) and height its
// real members span, in metres.
struct BodyStyleInfo {
  BodyStyle style;
  Family family;
  const char* name;
  uint32_t slots;
  DimensionRange length;
  DimensionRange width;
  DimensionRange height;
};
// The style's row of the table in vehicle_specs.cpp (the first row for an
// id outside the list).
const BodyStyleInfo& body_style_info(BodyStyle style);
// Upper bound on generate_fleet's count, so a bad argument cannot exhaust memory.
constexpr uint32_t kMaxFleetSize = 100000;

// "sedan", "van", "truck", "tracked", "pickup", "bus", "apc", "suv".
const char* family_name(Family family);
// Parses a family name; false if unknown.
bool parse_family(const std::string& name, Family* family);

// Everything that makes one vehicle: the generator draws it, the builder
// turns it into triangles. Lengths in metres. Fields a family does not use
// keep their defaults.
struct VehicleSpec {
  Family family = Family::kSedan;
  BodyStyle style = BodyStyle::kNotchback;
  uint32_t index = 0;
  std::string name;  // family-index, e.g. "sedan-03"

  double length = 4.5;             // bumper to bumper (hull for tracked)
  double width = 1.8;              // body width, mirrors excluded
  double height = 1.45;            // overall: roof with its rack, cargo box or turret top
  double ground_clearance = 0.16;  // hull underside above ground
  double belt_height = 0.85;       // top of the lower body (bonnet level)

  double front_length = 1.2;     // bonnet, truck cab, glacis run or bus front overhang
  double rear_length = 0.9;      // boot, bus rear overhang, truck rear overhang
  double cabin_length = 2.0;     // pickup cab
  double windscreen_run = 0.7;   // horizontal run of the sloped windscreen
  double rear_window_run = 0.5;  // horizontal run of the rear window
  double tumblehome = 0.15;      // roof narrower than the body, per side
  double rear_height = 2.6;      // truck load top (box, tipper body) / tracked superstructure top
  double cab_height = 2.6;       // truck cab roof

  double wheel_radius = 0.31;
  double wheel_width = 0.21;
  uint32_t axles = 2;         // 0 for tracked vehicles
  double axle_spacing = 2.7;  // wheelbase (2 axles) or spacing of adjacent axles
  double axle_shift = 0.0;    // wheel set offset along x from the centre
  double track_width = 0.55;  // tracked: width of each track

  bool roof_rack = false;  // rails and bars (cars), air-conditioning unit (buses)
  bool spoiler = false;
  bool spare_wheel = false;
  bool flatbed = false;    // truck: flatbed or dropside instead of a cargo box
  bool bed_cover = false;  // pickup: closed tonneau cover
  bool canopy = false;     // pickup: hardtop over the bed up to the cab roof
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
// names are unique. A family's members take its body styles in turn (the
// cycle of kStyleCycle slots, started at a seed's offset), so any
// kStyleCycle consecutive members of a family hold every style of it in its
// share. count is clamped to kMaxFleetSize.
std::vector<VehicleSpec> fleet_specs(uint32_t count, uint64_t seed);
std::vector<Mesh> generate_fleet(uint32_t count, uint64_t seed);

// Flat square ground of side 2*half_size at height z (normal up), meshed on
// a grid; with bump_height > 0 every grid vertex is raised or lowered by up
// to that much (deterministic from seed). A bad size gives an empty mesh.
Mesh make_ground_patch(double half_size, double z, double bump_height = 0.0, uint64_t seed = 0);

}  // namespace spinhash::host
