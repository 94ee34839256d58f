// Passenger-car families: sedan, the two-box bodies (vans, MPVs, SUVs) and
// pickups. All share a lower body (bumpers, bonnet, boot) and a greenhouse
// cabin with a sloped windscreen.
#include "mesh/vehicle_builders.hpp"
#include "mesh/vehicle_parts.hpp"

#include <algorithm>

namespace spinhash::host::vehicle {
namespace {

// Lower-body shape (m): bumpers are chamfered and slightly narrower so the
// corners read as rounded; the bonnet drops towards the nose.
constexpr double kNoseUndercut = 0.20;
constexpr double kTailUndercut = 0.12;
constexpr double kBumperHeight = 0.27;
constexpr double kBumperNarrowing = 0.06;
constexpr double kNoseSetback = 0.08;
constexpr double kBonnetDrop = 0.08;
constexpr double kTailSetback = 0.06;
// Parts overlap by this much so no seam opens between them.
constexpr double kOverlap = 0.02;
// The roof keeps at least this fraction of the cabin length.
constexpr double kMinRoofFraction = 0.30;
// Wheels: outer face this far inside the body side.
constexpr double kCarWheelInset = 0.03;
// Roof rack rails and cross bars.
constexpr double kRailInset = 0.08;
constexpr double kRailWidth = 0.05;
constexpr double kRailHeight = 0.06;
constexpr double kRailLengthFraction = 0.85;
constexpr double kCrossBarWidth = 0.05;
constexpr double kCrossBarSpread = 0.6;  // bars at +-this fraction of the rail half length
// The rack's top above the roof: the spec's height is the rack's top.
constexpr double kRackRise = kRailHeight + kCrossBarWidth;
// Mirrors (m): size and position relative to the windscreen base.
constexpr double kMirrorLength = 0.10;
constexpr double kMirrorReach = 0.18;
constexpr double kMirrorHeight = 0.12;
constexpr double kMirrorLift = 0.10;
// Boot spoiler lip.
constexpr double kSpoilerLength = 0.16;
constexpr double kSpoilerHeight = 0.09;
constexpr double kSpoilerSideInset = 0.10;
// Off-roader spare wheel on the tailgate.
constexpr double kSpareWheelLift = 0.25;
constexpr double kSpareWheelGap = 0.01;
// Pickup bed.
constexpr double kBedDepth = 0.45;
constexpr double kBedWall = 0.06;
constexpr double kBedCoverThickness = 0.04;
// Pickup canopy (hardtop): narrower than the bed, just below the cab roof.
constexpr double kCanopyInset = 0.04;
constexpr double kCanopyBelowRoof = 0.04;

// Side profile of the lower body between x_rear and x_front; with a
// rounded tail the rear is chamfered like a bumper, else it is a flat wall
// (the front of a pickup bed).
void add_lower_body(Mesh* mesh, const VehicleSpec& s, double x_rear, double x_front, double x_bonnet_rear,
                    bool rounded_tail) {
  const double cl = s.ground_clearance;
  const double zb = s.belt_height;
  const double hw = 0.5 * s.width;
  const double hw_bumper = hw - kBumperNarrowing;
  std::vector<ProfilePoint> profile = {
      {x_front - kNoseUndercut, cl, hw_bumper},
      {x_front, cl + kBumperHeight, hw_bumper},
      {x_front - kNoseSetback, zb - kBonnetDrop, hw},
      {x_bonnet_rear, zb, hw},
  };
  if (rounded_tail) {
    profile.push_back({x_rear + kTailSetback, zb, hw});
    profile.push_back({x_rear, cl + kBumperHeight, hw_bumper});
    profile.push_back({x_rear + kTailUndercut, cl, hw_bumper});
  } else {
    profile.push_back({x_rear, zb, hw});
    profile.push_back({x_rear, cl, hw});
  }
  add_profile_prism(mesh, profile);
}

struct Cabin {
  double x_rear;   // rear base
  double x_front;  // windscreen base
  double z_roof;
  double windscreen_run;
  double rear_run;
};

// Shrinks the windscreen and rear-window runs so the roof keeps its length.
Cabin fit_cabin(Cabin c) {
  const double base = c.x_front - c.x_rear;
  const double max_runs = (1.0 - kMinRoofFraction) * base;
  const double runs = c.windscreen_run + c.rear_run;
  if (runs > max_runs) {
    c.windscreen_run *= max_runs / runs;
    c.rear_run *= max_runs / runs;
  }
  return c;
}

void add_cabin(Mesh* mesh, const VehicleSpec& s, const Cabin& c) {
  const double z0 = s.belt_height - kOverlap;
  const double hw = 0.5 * s.width - kBumperNarrowing;
  const double hw_roof = 0.5 * s.width - s.tumblehome;
  add_profile_prism(mesh, {{c.x_rear, z0, hw},
                           {c.x_front, z0, hw},
                           {c.x_front - c.windscreen_run, c.z_roof, hw_roof},
                           {c.x_rear + c.rear_run, c.z_roof, hw_roof}});
}

void add_roof_rack(Mesh* mesh, const VehicleSpec& s, const Cabin& c) {
  const double roof_front = c.x_front - c.windscreen_run;
  const double roof_rear = c.x_rear + c.rear_run;
  const double mid = 0.5 * (roof_front + roof_rear);
  const double half = 0.5 * kRailLengthFraction * (roof_front - roof_rear);
  const double y = 0.5 * s.width - s.tumblehome - kRailInset;
  const double z0 = c.z_roof - kOverlap;
  const double z1 = c.z_roof + kRailHeight;
  for (double side : {-1.0, 1.0}) {
    add_box(mesh, {mid - half, side * y - 0.5 * kRailWidth, z0},
            {mid + half, side * y + 0.5 * kRailWidth, z1});
  }
  for (double x : {mid - kCrossBarSpread * half, mid + kCrossBarSpread * half}) {
    add_box(mesh, {x - 0.5 * kCrossBarWidth, -y, z1 - kOverlap},
            {x + 0.5 * kCrossBarWidth, y, z1 + kCrossBarWidth});
  }
}

void add_mirrors(Mesh* mesh, const VehicleSpec& s, double x_windscreen) {
  const double y0 = 0.5 * s.width - kBumperNarrowing;
  const double z0 = s.belt_height + kMirrorLift;
  for (double side : {-1.0, 1.0}) {
    const double ya = side * y0;
    const double yb = side * (y0 + kMirrorReach);
    add_box(mesh, {x_windscreen - kMirrorLength, std::min(ya, yb), z0},
            {x_windscreen, std::max(ya, yb), z0 + kMirrorHeight});
  }
}

// The roof under its rack, if any: the spec's height is the overall height.
double roof_height(const VehicleSpec& s) { return s.roof_rack ? s.height - kRackRise : s.height; }

std::vector<double> car_axles(const VehicleSpec& s) {
  return {s.axle_shift - 0.5 * s.axle_spacing, s.axle_shift + 0.5 * s.axle_spacing};
}

}  // namespace

void build_sedan(const VehicleSpec& s, Mesh* mesh) {
  const double front = 0.5 * s.length;
  const double rear = -front;
  const double windscreen = front - s.front_length;
  add_lower_body(mesh, s, rear, front, windscreen, true);
  const Cabin cabin =
      fit_cabin({rear + s.rear_length, windscreen, roof_height(s), s.windscreen_run, s.rear_window_run});
  add_cabin(mesh, s, cabin);
  add_mirrors(mesh, s, windscreen);
  add_wheel_pairs(mesh, s, car_axles(s), kCarWheelInset);
  if (s.roof_rack) add_roof_rack(mesh, s, cabin);
  if (s.spoiler) {
    const double y = 0.5 * s.width - kSpoilerSideInset;
    add_box(mesh, {rear + kTailSetback, -y, s.belt_height - kOverlap},
            {rear + kTailSetback + kSpoilerLength, y, s.belt_height + kSpoilerHeight});
  }
}

void build_two_box(const VehicleSpec& s, Mesh* mesh) {
  const double front = 0.5 * s.length;
  const double rear = -front;
  const double windscreen = front - s.front_length;
  add_lower_body(mesh, s, rear, front, windscreen, true);
  const Cabin cabin =
      fit_cabin({rear + kTailSetback, windscreen, roof_height(s), s.windscreen_run, s.rear_window_run});
  add_cabin(mesh, s, cabin);
  add_mirrors(mesh, s, windscreen);
  add_wheel_pairs(mesh, s, car_axles(s), kCarWheelInset);
  if (s.roof_rack) add_roof_rack(mesh, s, cabin);
  if (s.spare_wheel) {
    const double x = rear + kTailSetback - kSpareWheelGap - 0.5 * s.wheel_width;
    add_cylinder(mesh, {x, 0.0, s.belt_height + kSpareWheelLift - s.wheel_radius}, Axis::kX, s.wheel_radius,
                 s.wheel_width, kWheelSegments);
  }
}

void build_pickup(const VehicleSpec& s, Mesh* mesh) {
  const double front = 0.5 * s.length;
  const double rear = -front;
  const double windscreen = front - s.front_length;
  const double bed_front = windscreen - s.cabin_length;
  add_lower_body(mesh, s, bed_front, front, windscreen, false);
  const Cabin cabin = fit_cabin({bed_front, windscreen, roof_height(s), s.windscreen_run, s.rear_window_run});
  add_cabin(mesh, s, cabin);
  add_mirrors(mesh, s, windscreen);
  add_wheel_pairs(mesh, s, car_axles(s), kCarWheelInset);
  if (s.roof_rack) add_roof_rack(mesh, s, cabin);

  // The open bed: floor, two side walls, tailgate; the cab wall closes it.
  const double hw = 0.5 * s.width;
  const double floor_top = s.belt_height - kBedDepth;
  const double bed_end = bed_front + kOverlap;
  add_box(mesh, {rear + kTailUndercut, -hw, s.ground_clearance}, {bed_end, hw, floor_top});
  for (double side : {-1.0, 1.0}) {
    const double y_outer = side * hw;
    const double y_inner = side * (hw - kBedWall);
    add_box(mesh, {rear, std::min(y_outer, y_inner), floor_top - kOverlap},
            {bed_end, std::max(y_outer, y_inner), s.belt_height});
  }
  add_box(mesh, {rear, -hw, s.ground_clearance + kBumperHeight}, {rear + kBedWall, hw, s.belt_height});
  if (s.bed_cover) {
    add_box(mesh, {rear, -hw, s.belt_height - kOverlap}, {bed_end, hw, s.belt_height + kBedCoverThickness});
  }
  if (s.canopy) {
    const double hw_canopy = hw - kCanopyInset;
    add_box(mesh, {rear, -hw_canopy, s.belt_height - kOverlap},
            {bed_end, hw_canopy, cabin.z_roof - kCanopyBelowRoof});
  }
}

}  // namespace spinhash::host::vehicle
