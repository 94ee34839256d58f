// Draws VehicleSpecs: the dimension ranges and option odds of each family.
// Ranges are those of common real vehicles; within a family, members share
// the layout and differ by tens of centimetres and by details.
#include "mesh/seeded_random.hpp"
#include "mesh/vehicle_generator.hpp"

#include <cmath>
#include <cstdio>

namespace spinhash::host {
namespace {

// Golden-ratio (Weyl) sequence: consecutive members' lengths are far apart
// in the family's range, and no two of a small fleet coincide.
constexpr double kGoldenFraction = 0.6180339887498949;
// Streams of mix_seed, so families and members draw independent numbers.
constexpr uint64_t kLengthStream = 0x1000;
constexpr uint64_t kMemberStream = 0x2000;

double lerp(double lo, double hi, double t) { return lo + (hi - lo) * t; }

void draw_sedan(SeededRandom& rng, double t, VehicleSpec* s) {
  s->length = lerp(3.8, 5.2, t);
  s->width = rng.uniform(1.68, 1.90);
  s->height = rng.uniform(1.38, 1.52);
  s->ground_clearance = rng.uniform(0.13, 0.19);
  s->belt_height = s->ground_clearance + rng.uniform(0.62, 0.74);
  s->hatchback = rng.chance(0.3);
  s->front_length = s->length * rng.uniform(0.24, 0.30);
  s->rear_length = s->hatchback ? 0.12 : s->length * rng.uniform(0.17, 0.24);
  s->windscreen_run = rng.uniform(0.55, 0.85);
  s->rear_window_run = s->hatchback ? rng.uniform(0.35, 0.6) : rng.uniform(0.4, 0.7);
  s->tumblehome = rng.uniform(0.10, 0.20);
  s->wheel_radius = rng.uniform(0.29, 0.34);
  s->wheel_width = rng.uniform(0.19, 0.24);
  s->axle_spacing = s->length * rng.uniform(0.56, 0.61);
  s->axle_shift = rng.uniform(0.0, 0.12);
  s->roof_rack = rng.chance(0.3);
  s->spoiler = !s->hatchback && rng.chance(0.25);
}

void draw_van(SeededRandom& rng, double t, VehicleSpec* s) {
  s->length = lerp(4.3, 5.4, t);
  s->width = rng.uniform(1.80, 2.00);
  s->height = rng.uniform(1.65, 2.10);
  s->ground_clearance = rng.uniform(0.18, 0.26);
  s->belt_height = s->ground_clearance + rng.uniform(0.72, 0.85);
  s->front_length = rng.uniform(0.75, 1.25);
  s->windscreen_run = rng.uniform(0.45, 0.85);
  s->rear_window_run = rng.uniform(0.05, 0.20);
  s->tumblehome = rng.uniform(0.06, 0.14);
  s->wheel_radius = rng.uniform(0.33, 0.40);
  s->wheel_width = rng.uniform(0.21, 0.27);
  s->axle_spacing = s->length * rng.uniform(0.58, 0.63);
  s->axle_shift = rng.uniform(-0.05, 0.10);
  s->spare_wheel = rng.chance(0.4);
  s->roof_rack = rng.chance(0.4);
}

void draw_truck(SeededRandom& rng, double t, VehicleSpec* s) {
  s->length = lerp(6.0, 8.0, t);
  s->width = rng.uniform(2.30, 2.50);
  s->height = rng.uniform(2.60, 3.10);  // cab roof
  s->ground_clearance = rng.uniform(0.35, 0.45);
  s->belt_height = s->ground_clearance + rng.uniform(1.05, 1.30);
  s->front_length = rng.uniform(1.60, 2.20);  // cab length
  s->windscreen_run = rng.uniform(0.15, 0.40);
  s->flatbed = rng.chance(0.4);
  s->rear_height = s->flatbed ? 0.0 : rng.uniform(2.5, 3.3);  // cargo box top
  s->wheel_radius = rng.uniform(0.45, 0.52);
  s->wheel_width = rng.uniform(0.28, 0.36);
  s->axles = (s->length > 6.8 && rng.chance(0.5)) ? 3 : 2;
  s->axle_spacing = rng.uniform(1.25, 1.40);  // tandem spacing
  s->spare_wheel = rng.chance(0.35);          // behind the cab
}

void draw_tracked(SeededRandom& rng, double t, VehicleSpec* s) {
  s->length = lerp(6.2, 7.6, t);
  s->width = rng.uniform(3.20, 3.60);
  s->ground_clearance = rng.uniform(0.40, 0.50);
  s->belt_height = rng.uniform(1.70, 2.00);  // hull top
  s->front_length = rng.uniform(1.2, 1.8);   // glacis run
  s->track_width = rng.uniform(0.50, 0.65);
  s->axles = 0;
  s->turret = rng.chance(0.85);
  s->turret_length = rng.uniform(2.2, 3.2);
  s->turret_width = std::fmin(rng.uniform(2.0, 2.6), s->width - 0.5);
  s->turret_height = rng.uniform(0.60, 0.85);
  s->turret_x = rng.uniform(-0.8, 0.6);
  s->barrel = s->turret && rng.chance(0.7);
  s->barrel_length = rng.uniform(3.0, 5.0);
  // Without a turret: a casemate superstructure up to rear_height.
  s->rear_height = s->belt_height + (s->turret ? 0.0 : rng.uniform(0.5, 0.9));
  s->height = s->turret ? s->belt_height + s->turret_height : s->rear_height;
}

void draw_pickup(SeededRandom& rng, double t, VehicleSpec* s) {
  s->length = lerp(4.9, 5.9, t);
  s->width = rng.uniform(1.80, 2.00);
  s->height = rng.uniform(1.75, 1.95);
  s->ground_clearance = rng.uniform(0.22, 0.30);
  s->belt_height = s->ground_clearance + rng.uniform(0.75, 0.90);
  s->front_length = rng.uniform(1.3, 1.7);
  s->cabin_length = rng.chance(0.5) ? rng.uniform(1.5, 1.8) : rng.uniform(2.3, 2.6);
  s->rear_length = s->length - s->front_length - s->cabin_length;  // bed
  s->windscreen_run = rng.uniform(0.45, 0.70);
  s->rear_window_run = rng.uniform(0.05, 0.15);
  s->tumblehome = rng.uniform(0.08, 0.15);
  s->wheel_radius = rng.uniform(0.36, 0.42);
  s->wheel_width = rng.uniform(0.24, 0.30);
  s->axle_spacing = s->length * rng.uniform(0.58, 0.62);
  s->axle_shift = rng.uniform(0.0, 0.15);
  s->bed_cover = rng.chance(0.3);
  s->roof_rack = rng.chance(0.25);
}

void draw_bus(SeededRandom& rng, double t, VehicleSpec* s) {
  s->length = lerp(9.0, 12.5, t);
  s->width = rng.uniform(2.45, 2.55);
  s->height = rng.uniform(2.90, 3.30);
  s->ground_clearance = rng.uniform(0.30, 0.38);
  s->front_length = rng.uniform(2.0, 2.6);  // front overhang
  s->rear_length = rng.uniform(2.6, 3.4);   // rear overhang
  s->windscreen_run = rng.uniform(0.10, 0.30);
  s->wheel_radius = rng.uniform(0.48, 0.52);
  s->wheel_width = rng.uniform(0.28, 0.32);
  s->axles = (s->length > 11.5 && rng.chance(0.6)) ? 3 : 2;
  s->axle_spacing = rng.uniform(1.3, 1.45);
  s->roof_rack = rng.chance(0.5);  // roof air-conditioning unit
}

void draw_apc(SeededRandom& rng, double t, VehicleSpec* s) {
  s->length = lerp(6.5, 8.0, t);
  s->width = rng.uniform(2.60, 2.90);
  s->ground_clearance = rng.uniform(0.45, 0.55);
  s->belt_height = rng.uniform(2.00, 2.30);  // hull top
  s->front_length = rng.uniform(1.0, 1.6);   // glacis run
  s->wheel_radius = rng.uniform(0.55, 0.62);
  s->wheel_width = rng.uniform(0.36, 0.44);
  s->axles = rng.chance(0.75) ? 4 : 3;
  s->axle_spacing = rng.uniform(1.30, 1.55);
  s->axle_shift = rng.uniform(-0.3, 0.1);
  s->turret = rng.chance(0.6);
  s->turret_length = rng.uniform(1.2, 1.7);
  s->turret_width = rng.uniform(1.1, 1.5);
  s->turret_height = rng.uniform(0.45, 0.65);
  s->turret_x = rng.uniform(-0.6, 0.4);
  s->barrel = s->turret;
  s->barrel_length = rng.uniform(1.8, 2.6);
  s->height = s->belt_height + (s->turret ? s->turret_height : 0.0);
}

}  // namespace

VehicleSpec make_vehicle_spec(Family family, uint32_t index, uint64_t seed) {
  const auto family_id = static_cast<uint64_t>(family);
  const uint64_t family_seed = mix_seed(seed, family_id);
  SeededRandom start_rng(mix_seed(family_seed, kLengthStream));
  const double start = start_rng.uniform01();
  double t = start + kGoldenFraction * index;
  t -= std::floor(t);
  SeededRandom rng(mix_seed(mix_seed(family_seed, kMemberStream), index));

  VehicleSpec spec;
  spec.family = family;
  spec.index = index;
  char name[64];
  std::snprintf(name, sizeof name, "%s-%02u", family_name(family), index);
  spec.name = name;
  switch (family) {
    case Family::kSedan: draw_sedan(rng, t, &spec); break;
    case Family::kVan: draw_van(rng, t, &spec); break;
    case Family::kTruck: draw_truck(rng, t, &spec); break;
    case Family::kTracked: draw_tracked(rng, t, &spec); break;
    case Family::kPickup: draw_pickup(rng, t, &spec); break;
    case Family::kBus: draw_bus(rng, t, &spec); break;
    case Family::kApc: draw_apc(rng, t, &spec); break;
  }
  return spec;
}

}  // namespace spinhash::host
