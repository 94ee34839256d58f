// Heavy families: truck (cab + cargo box, flatbed, tipper body or a tractor
// unit's fifth wheel), bus, tracked vehicle (hull, tracks, turret, barrel)
// and wheeled APC (boat hull, 2-4 axles).
#include "mesh/vehicle_builders.hpp"
#include "mesh/vehicle_parts.hpp"

#include <algorithm>

namespace spinhash::host::vehicle {
namespace {

// Parts overlap by this much so no seam opens between them.
constexpr double kOverlap = 0.02;
constexpr double kRoofNarrowing = 0.05;

// Truck (m).
constexpr double kTruckWheelInset = 0.02;
constexpr double kFrontAxleInCab = 0.55;  // fraction of the cab length
constexpr double kChassisHalfWidth = 0.55;
constexpr double kChassisDepth = 0.30;
constexpr double kDeckAboveWheels = 0.12;
constexpr double kCabGap = 0.12;
constexpr double kFlatbedThickness = 0.15;
constexpr double kHeadboardThickness = 0.12;
constexpr double kHeadboardHeight = 1.0;
constexpr double kFuelTankRadius = 0.28;
constexpr double kFuelTankLength = 1.0;
constexpr double kFuelTankInset = 0.40;
constexpr uint32_t kTankSegments = 12;
constexpr double kTipperFloor = 0.12;          // tipper body floor thickness
constexpr double kTipperWall = 0.08;           // its side walls, tailgate and headboard
constexpr double kTipperHeadboardRise = 0.15;  // the headboard stands above the sides
constexpr double kFifthWheelLength = 0.9;      // tractor unit coupling plate
constexpr double kFifthWheelHalfWidth = 0.45;
constexpr double kFifthWheelHeight = 0.18;

// Bus (m).
constexpr double kBusNoseDrop = 0.35;
constexpr double kBusTailDrop = 0.20;
constexpr double kBusTailSetback = 0.15;
constexpr double kBusWheelInset = 0.03;
constexpr double kAcUnitHalfLength = 1.0;
constexpr double kAcUnitHalfWidth = 0.8;
constexpr double kAcUnitHeight = 0.25;  // the spec's height is the unit's top

// Tracked vehicle (m).
constexpr double kTrackLengthFraction = 0.96;
constexpr double kTrackAboveHull = 0.50;  // track top above hull underside
constexpr double kTrackEndRun = 0.45;     // bottom run ends short of the idlers
constexpr double kTrackTopSetback = 0.25;
constexpr double kTrackMidFraction = 0.55;  // height of the idler/sprocket corner
constexpr double kLowerHullRearInset = 0.30;
constexpr double kLowerGlacisRun = 0.60;
constexpr double kHullTopNarrowing = 0.10;
constexpr double kHullRearSetback = 0.10;
constexpr double kTurretTopScale = 0.85;
constexpr double kBarrelRadius = 0.08;
constexpr uint32_t kBarrelSegments = 10;
constexpr double kBarrelInTurret = 0.30;  // breech length hidden in the turret
constexpr double kMantletLength = 0.35;
constexpr double kMantletHalfWidth = 0.35;
constexpr double kMantletHalfHeight = 0.22;
constexpr double kSuperstructureInset = 0.45;
constexpr double kSuperstructureReach = 1.0;  // ahead of turret_x
constexpr double kEngineDeckLength = 1.2;
constexpr double kEngineDeckInset = 0.70;
constexpr double kEngineDeckHeight = 0.12;

// Wheeled APC (m).
constexpr double kApcBottomNarrowing = 0.35;
constexpr double kApcNoseNarrowing = 0.25;
constexpr double kApcTopNarrowing = 0.05;
constexpr double kApcRearUndercut = 0.30;
constexpr double kApcNoseHeight = 0.55;
constexpr double kApcLowerGlacisFraction = 0.6;
constexpr double kApcTurretTopScale = 0.80;
constexpr double kApcBarrelRadius = 0.05;
constexpr double kDoorHalfWidth = 0.50;
constexpr double kDoorThickness = 0.06;
constexpr double kDoorBottomLift = 0.40;
constexpr double kDoorTopDrop = 0.30;

void add_turret(Mesh* mesh, const VehicleSpec& s, double z_hull_top, double top_scale, double barrel_radius) {
  const double z1 = z_hull_top + s.turret_height;
  add_plan_frustum(mesh, hexagon_plan(s.turret_length, s.turret_width), {s.turret_x, 0.0},
                   z_hull_top - kOverlap, z1, top_scale);
  if (!s.barrel) return;
  const double z_axis = z_hull_top + 0.5 * s.turret_height;
  const double x_front = s.turret_x + 0.5 * s.turret_length;
  add_box(mesh, {x_front - kMantletLength, -kMantletHalfWidth, z_axis - kMantletHalfHeight},
          {x_front + kOverlap, kMantletHalfWidth, z_axis + kMantletHalfHeight});
  const double x_mid = x_front - kBarrelInTurret + 0.5 * s.barrel_length;
  add_cylinder(mesh, {x_mid, 0.0, z_axis}, Axis::kX, barrel_radius, s.barrel_length, kBarrelSegments);
}

}  // namespace

void build_truck(const VehicleSpec& s, Mesh* mesh) {
  const double front = 0.5 * s.length;
  const double rear = -front;
  const double cab_rear = front - s.front_length;
  const double hw = 0.5 * s.width;
  const double cl = s.ground_clearance;
  add_profile_prism(mesh, {{cab_rear, cl, hw},
                           {front, cl, hw},
                           {front, s.belt_height, hw},
                           {front - s.windscreen_run, s.cab_height, hw - kRoofNarrowing},
                           {cab_rear, s.cab_height, hw - kRoofNarrowing}});
  add_box(mesh, {rear + kOverlap, -kChassisHalfWidth, cl},
          {cab_rear + kOverlap, kChassisHalfWidth, cl + kChassisDepth});

  // Frame over the wheels, then the load on it.
  const double deck = std::max(cl + kChassisDepth, 2.0 * s.wheel_radius + kDeckAboveWheels);
  const double load_front = cab_rear - kCabGap;
  add_box(mesh, {rear, -kChassisHalfWidth, cl + kChassisDepth - kOverlap},
          {load_front, kChassisHalfWidth, deck + kOverlap});
  if (s.style == BodyStyle::kTractorUnit) {
    const double x = rear + s.rear_length + 0.5 * kFifthWheelLength;
    add_box(mesh, {x - 0.5 * kFifthWheelLength, -kFifthWheelHalfWidth, deck},
            {x + 0.5 * kFifthWheelLength, kFifthWheelHalfWidth, deck + kFifthWheelHeight});
  } else if (s.style == BodyStyle::kTipper) {
    // Open body: floor, side walls, tailgate and a taller headboard.
    const double top = s.rear_height - kTipperHeadboardRise;
    const double floor_top = deck + kTipperFloor;
    add_box(mesh, {rear, -hw, deck}, {load_front, hw, floor_top});
    for (double side : {-1.0, 1.0}) {
      const double y_outer = side * hw;
      const double y_inner = side * (hw - kTipperWall);
      add_box(mesh, {rear, std::min(y_outer, y_inner), floor_top - kOverlap},
              {load_front, std::max(y_outer, y_inner), top});
    }
    add_box(mesh, {rear, -hw, floor_top - kOverlap}, {rear + kTipperWall, hw, top});
    add_box(mesh, {load_front - kTipperWall, -hw, floor_top - kOverlap}, {load_front, hw, s.rear_height});
  } else if (s.flatbed) {
    add_box(mesh, {rear, -hw, deck}, {load_front, hw, deck + kFlatbedThickness});
    add_box(mesh, {load_front - kHeadboardThickness, -hw, deck + kFlatbedThickness - kOverlap},
            {load_front, hw, deck + kHeadboardHeight});
  } else {
    add_box(mesh, {rear, -hw, deck}, {load_front, hw, s.rear_height});
  }

  const double front_axle = front - kFrontAxleInCab * s.front_length;
  const uint32_t rear_axles = s.axles > 1 ? s.axles - 1 : 1;
  const double rear_center = rear + s.rear_length + 0.5 * (rear_axles - 1) * s.axle_spacing;
  std::vector<double> axles = axle_group(rear_center, rear_axles, s.axle_spacing);
  axles.push_back(front_axle);
  add_wheel_pairs(mesh, s, axles, kTruckWheelInset);

  // Fuel tank (right) and, optionally, a spare wheel (left) between the axles.
  const double x_between = 0.5 * (front_axle + rear_center + 0.5 * (rear_axles - 1) * s.axle_spacing);
  add_cylinder(mesh, {x_between, -(hw - kFuelTankInset), cl + kFuelTankRadius}, Axis::kX, kFuelTankRadius,
               kFuelTankLength, kTankSegments);
  if (s.spare_wheel) {
    add_cylinder(mesh, {x_between, hw - kFuelTankInset, cl + s.wheel_radius}, Axis::kY, s.wheel_radius,
                 s.wheel_width, kWheelSegments);
  }
}

void build_bus(const VehicleSpec& s, Mesh* mesh) {
  const double front = 0.5 * s.length;
  const double rear = -front;
  const double hw = 0.5 * s.width;
  const double cl = s.ground_clearance;
  const double hw_roof = hw - kRoofNarrowing;
  const double roof = s.roof_rack ? s.height - kAcUnitHeight : s.height;
  add_profile_prism(mesh, {{rear, cl, hw},
                           {front, cl, hw},
                           {front, roof - kBusNoseDrop, hw},
                           {front - s.windscreen_run, roof, hw_roof},
                           {rear + kBusTailSetback, roof, hw_roof},
                           {rear, roof - kBusTailDrop, hw}});
  const uint32_t rear_axles = s.axles > 1 ? s.axles - 1 : 1;
  std::vector<double> axles = axle_group(rear + s.rear_length, rear_axles, s.axle_spacing);
  axles.push_back(front - s.front_length);
  add_wheel_pairs(mesh, s, axles, kBusWheelInset);
  if (s.roof_rack) {
    add_box(mesh, {-kAcUnitHalfLength, -kAcUnitHalfWidth, roof - kOverlap},
            {kAcUnitHalfLength, kAcUnitHalfWidth, s.height});
  }
}

void build_tracked(const VehicleSpec& s, Mesh* mesh) {
  const double front = 0.5 * s.length;
  const double rear = -front;
  const double hw = 0.5 * s.width;
  const double cl = s.ground_clearance;
  const double top = s.belt_height;
  const double track_top = cl + kTrackAboveHull;
  const double lt = 0.5 * kTrackLengthFraction * s.length;
  const double tw = s.track_width;
  for (double side : {-1.0, 1.0}) {
    add_profile_prism(mesh,
                      {{-lt + kTrackEndRun, 0.0, 0.5 * tw},
                       {lt - kTrackEndRun, 0.0, 0.5 * tw},
                       {lt, kTrackMidFraction * track_top, 0.5 * tw},
                       {lt - kTrackTopSetback, track_top, 0.5 * tw},
                       {-lt + kTrackTopSetback, track_top, 0.5 * tw},
                       {-lt, kTrackMidFraction * track_top, 0.5 * tw}},
                      side * (hw - 0.5 * tw));
  }
  // Lower hull between the tracks, then the upper hull over them.
  const double hw_low = hw - tw + kOverlap;
  add_profile_prism(mesh, {{rear + kLowerHullRearInset, cl, hw_low},
                           {front - kLowerGlacisRun, cl, hw_low},
                           {front, track_top, hw_low},
                           {rear + kLowerHullRearInset, track_top, hw_low}});
  const double hw_top = hw - kHullTopNarrowing;
  add_profile_prism(mesh, {{rear, track_top - kOverlap, hw},
                           {front, track_top - kOverlap, hw},
                           {front - s.front_length, top, hw_top},
                           {rear + kHullRearSetback, top, hw_top}});
  add_box(mesh, {rear + kHullRearSetback, -(hw - kEngineDeckInset), top - kOverlap},
          {rear + kHullRearSetback + kEngineDeckLength, hw - kEngineDeckInset, top + kEngineDeckHeight});
  if (s.turret) {
    add_turret(mesh, s, top, kTurretTopScale, kBarrelRadius);
  } else {
    // Casemate superstructure (self-propelled gun / carrier).
    add_box(mesh, {rear + kHullRearSetback, -(hw - kSuperstructureInset), top - kOverlap},
            {s.turret_x + kSuperstructureReach, hw - kSuperstructureInset, s.rear_height});
  }
}

void build_apc(const VehicleSpec& s, Mesh* mesh) {
  const double front = 0.5 * s.length;
  const double rear = -front;
  const double hw = 0.5 * s.width;
  const double cl = s.ground_clearance;
  const double top = s.belt_height;
  const double hw_bottom = hw - kApcBottomNarrowing;
  const double hw_top = hw - kApcTopNarrowing;
  // The rear door stands out of the hull's back: the hull ends inside the length.
  const double back = rear + kDoorThickness;
  add_profile_prism(mesh, {{back + kApcRearUndercut, cl, hw_bottom},
                           {front - kApcLowerGlacisFraction * s.front_length, cl, hw_bottom},
                           {front, cl + kApcNoseHeight, hw - kApcNoseNarrowing},
                           {front - s.front_length, top, hw_top},
                           {back, top, hw_top},
                           {back, cl + kApcRearUndercut, hw_bottom}});
  add_wheel_pairs(mesh, s, axle_group(s.axle_shift, s.axles, s.axle_spacing), 0.0);
  add_box(mesh, {rear, -kDoorHalfWidth, cl + kDoorBottomLift},
          {back + kOverlap, kDoorHalfWidth, top - kDoorTopDrop});
  if (s.turret) add_turret(mesh, s, top, kApcTurretTopScale, kApcBarrelRadius);
}

}  // namespace spinhash::host::vehicle
