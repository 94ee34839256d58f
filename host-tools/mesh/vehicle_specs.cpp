// Draws VehicleSpecs: the body styles of each family, their real-world
// dimension ranges and option odds. Within a style, members share the
// layout and differ by tens of centimetres and by details.
#include "mesh/seeded_random.hpp"
#include "mesh/vehicle_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace spinhash::host {
namespace {

using Range = DimensionRange;

// The ranges come from manufacturers' published dimensions of current and
// recent models (length x width without mirrors x unladen height, m), and
// from the legal maxima of EU Council Directive 96/53/EC (width 2.55 m,
// rigid vehicle 12 m, height 4 m for international traffic). Where real
// members exceed what a scene keeps as one vehicle (SceneConfig: longer
// than 13 m, or a roof above the 3.8 m layer split: three-axle coaches,
// articulated lorries, double-deckers, 4 m box bodies), the range stops
// short of them.
constexpr BodyStyleInfo kStyles[kBodyStyleCount] = {
    // Fiat Panda 3.65 x 1.64 x 1.55, Toyota Yaris (hybrid) 3.94 x 1.75 x
    // 1.50, VW Polo 4.05 x 1.75 x 1.46, Honda Jazz 4.04 x 1.69 x 1.53, VW
    // Golf 4.28 x 1.79 x 1.46, Ford Focus 4.38 x 1.83 x 1.47.
    {BodyStyle::kHatchback, Family::kSedan, "hatchback", 7, {3.55, 4.40}, {1.62, 1.83}, {1.42, 1.56}},
    // Toyota Corolla saloon 4.63 x 1.78 x 1.44, Toyota Camry 4.89 x 1.84 x
    // 1.45, BMW 3 Series 4.71 x 1.83 x 1.44, Mercedes E-Class 4.92 x 1.85 x
    // 1.47, BMW 5 Series 5.06 x 1.87 x 1.48, Mercedes S-Class 5.18 x 1.92 x 1.50.
    {BodyStyle::kNotchback, Family::kSedan, "notchback", 5, {4.30, 5.20}, {1.70, 1.92}, {1.40, 1.51}},
    // Toyota Prius (hybrid) 4.54-4.60 x 1.76-1.78 x 1.43-1.49, Skoda Superb
    // 4.86 x 1.86 x 1.47, Tesla Model 3 4.69 x 1.85 x 1.44, Audi A5
    // Sportback 4.76 x 1.84 x 1.39.
    {BodyStyle::kFastback, Family::kSedan, "fastback", 3, {4.40, 5.05}, {1.74, 1.90}, {1.39, 1.50}},
    // Skoda Octavia Combi 4.69 x 1.83 x 1.47, VW Passat Variant 4.77 x 1.83
    // x 1.51 (with rails), Volvo V60 4.76 x 1.85 x 1.43, Dacia Logan MCV
    // 4.50 x 1.73 x 1.55.
    {BodyStyle::kEstate, Family::kSedan, "estate", 3, {4.25, 4.95}, {1.73, 1.90}, {1.43, 1.55}},
    // Mazda MX-5 3.92 x 1.73 x 1.23, Toyota GR86 4.27 x 1.78 x 1.31, Audi
    // TT 4.19 x 1.83 x 1.37, Porsche 911 4.52 x 1.85 x 1.30, BMW 4 Series
    // coupe 4.77 x 1.85 x 1.38, Ford Mustang 4.79 x 1.92 x 1.38.
    {BodyStyle::kCoupe, Family::kSedan, "coupe", 2, {3.95, 4.80}, {1.73, 1.92}, {1.25, 1.39}},
    // VW Touran 4.53 x 1.83 x 1.66, Renault Scenic 4.41 x 1.87 x 1.65,
    // Ford Galaxy 4.85 x 1.92 x 1.75, Toyota Sienna 5.18 x 2.00 x 1.77,
    // Citroen Berlingo 4.40 x 1.85 x 1.84, VW Caddy 4.50 x 1.86 x 1.82.
    {BodyStyle::kMpv, Family::kVan, "mpv", 7, {4.30, 5.20}, {1.78, 2.00}, {1.62, 1.88}},
    // VW Transporter 4.90-5.30 x 1.90 x 1.97, Ford Transit Custom
    // 4.97-5.34 x 1.99 x 1.97-2.02, Mercedes Vito 4.90-5.37 x 1.93 x 1.91,
    // Renault Trafic 5.00-5.40 x 1.96 x 1.97.
    {BodyStyle::kMidVan, Family::kVan, "van", 6, {4.80, 5.45}, {1.90, 2.00}, {1.88, 2.05}},
    // Mercedes Sprinter 5.27-6.97 x 2.02 x 2.36-2.84, Ford Transit
    // 5.53-6.70 x 2.06 x 2.29-2.78, Renault Master 5.05-6.85 x 2.07 x
    // 2.30-2.81, Fiat Ducato 4.96-6.36 x 2.05 x 2.25-2.76.
    {BodyStyle::kHighRoofVan, Family::kVan, "high-roof-van", 7, {5.00, 7.00}, {2.00, 2.07}, {2.25, 2.80}},
    // Fiat Strada 4.48 x 1.73 x 1.60, Ford Maverick 5.07 x 1.84 x 1.75,
    // Toyota Hilux 5.27-5.33 x 1.80-1.86 x 1.69-1.82, Ford Ranger 5.37 x
    // 1.92 x 1.85, Nissan Navara 5.26 x 1.85 x 1.84, Mitsubishi L200 5.30 x
    // 1.82 x 1.78, Isuzu D-Max 5.27 x 1.87 x 1.79, Jeep Gladiator 5.54 x
    // 1.89 x 1.86.
    {BodyStyle::kMidPickup, Family::kPickup, "midsize-pickup", 12, {4.45, 5.55}, {1.72, 1.92}, {1.60, 1.86}},
    // Ford F-150 5.32-6.19 x 2.03 x 1.91-1.99, Ram 1500 5.82-5.92 x 2.08 x
    // 1.97, Chevrolet Silverado 5.84 x 2.06 x 1.92, Toyota Tundra 5.81-6.27
    // x 2.04 x 1.98.
    {BodyStyle::kFullPickup, Family::kPickup, "fullsize-pickup", 8, {5.40, 6.30}, {2.00, 2.08}, {1.88, 2.00}},
    // Isuzu N-series 5.9-7.7 x 2.0 x 2.2-2.3 (cab), Mitsubishi Fuso Canter
    // 4.7-7.0 x 1.7-2.0 x 2.1-2.3, Iveco Daily chassis cab; box bodies to
    // 3.0-3.4 m.
    {BodyStyle::kLightTruck, Family::kTruck, "light-truck", 6, {5.00, 7.50}, {1.95, 2.25}, {2.20, 3.40}},
    // Mercedes Atego, MAN TGL/TGM, DAF XB, Volvo FL: 7-10.5 x 2.45-2.55
    // (96/53/EC: 2.55) x 2.7-3.3 (cab); box bodies to 3.7 m (real ones to 4 m).
    {BodyStyle::kRigidTruck, Family::kTruck, "rigid-truck", 7, {7.00, 10.50}, {2.45, 2.55}, {2.70, 3.70}},
    // MAN TGX, DAF XF, Volvo FH, Scania R tractor units (4x2, 6x2): 5.7-6.5
    // x 2.49-2.55 x 3.0-3.9 (low to high cab).
    {BodyStyle::kTractorUnit, Family::kTruck, "tractor-unit", 3, {5.70, 6.50}, {2.48, 2.55}, {3.00, 3.70}},
    // Construction tippers (Mercedes Arocs, MAN TGS 6x4): 6.5-9 x 2.50-2.55
    // x 2.9-3.3.
    {BodyStyle::kTipper, Family::kTruck, "tipper", 4, {6.50, 9.00}, {2.48, 2.55}, {2.90, 3.30}},
    // Alexander Dennis Enviro200 8.9-10.8 x 2.44 x 2.9-3.0, Solaris Urbino
    // 8.9 x 2.40 x 2.85, Mercedes Citaro K 10.6 x 2.55 x 3.1.
    {BodyStyle::kMidibus, Family::kBus, "midibus", 5, {8.00, 10.60}, {2.30, 2.55}, {2.80, 3.10}},
    // Mercedes Citaro 12.1 x 2.55 x 3.1, MAN Lion's City 12.2 x 2.55 x
    // 3.0-3.3 (roof batteries), Volvo 7900 12.0 x 2.55 x 3.3, Solaris
    // Urbino 12 x 2.55 x 3.0-3.3.
    {BodyStyle::kCityBus, Family::kBus, "city-bus", 9, {10.80, 12.20}, {2.50, 2.55}, {2.90, 3.35}},
    // Setra S 515 HD 12.2 x 2.55 x 3.7, Mercedes Tourismo 12.1 x 2.55 x
    // 3.7, Irizar i6 12.2 x 2.55 x 3.5, Volvo 9700 12.0 x 2.55 x 3.5-3.7.
    {BodyStyle::kCoach, Family::kBus, "coach", 6, {10.50, 12.50}, {2.50, 2.55}, {3.30, 3.72}},
    // Hull length, gun excluded: T-72 6.95 x 3.59 x 2.23, T-90 6.86 x 3.78
    // x 2.23, Leclerc 6.88 x 3.71 x 2.53, Leopard 2A4 7.72 x 3.75 x 2.48,
    // M1 Abrams 7.93 x 3.66 x 2.44, Merkava 4 7.60 x 3.72 x 2.66, Challenger
    // 2 8.30 x 3.52 x 2.49.
    {BodyStyle::kMainBattleTank, Family::kTracked, "mbt", 7, {6.80, 8.30}, {3.45, 3.80}, {2.20, 2.80}},
    // M2 Bradley 6.55 x 3.60 x 2.98, BMP-2 6.72 x 3.15 x 2.45, CV90 6.55 x
    // 3.10 x 2.70, Warrior 6.34 x 3.03 x 2.79, Marder 6.79 x 3.24 x 2.98.
    {BodyStyle::kIfv, Family::kTracked, "ifv", 6, {6.20, 7.40}, {3.00, 3.60}, {2.45, 3.00}},
    // M113 4.86 x 2.69 x 2.50, FV432 5.25 x 2.80 x 2.28, MT-LB 6.45 x 2.86 x 1.87.
    {BodyStyle::kTrackedCarrier,
     Family::kTracked,
     "tracked-carrier",
     4,
     {4.80, 6.50},
     {2.65, 3.20},
     {1.85, 2.60}},
    // Hull length: M109A6 6.19 x 3.15 x 3.25, AS-90 7.20 x 3.50 x 3.00,
    // 2S19 Msta 6.04 x 3.38 x 2.99, PzH 2000 7.87 x 3.58 x 3.40.
    {BodyStyle::kSelfPropelledGun, Family::kTracked, "sp-gun", 3, {6.00, 7.90}, {3.15, 3.60}, {2.95, 3.45}},
    // Boxer 7.93 x 2.99 x 2.37 (hull), Patria AMV 7.70 x 2.80 x 2.30,
    // BTR-80 7.65 x 2.90 x 2.41, Piranha V 7.80 x 2.99 x 2.40, VBCI 7.60 x
    // 2.98 x 3.00 (turret), LAV-25 6.39 x 2.50 x 2.69 (turret).
    {BodyStyle::kApc8x8, Family::kApc, "apc-8x8", 9, {6.40, 8.00}, {2.50, 3.00}, {2.25, 3.15}},
    // VAB 6x6 5.98 x 2.49 x 2.06, Fuchs 6.83 x 2.98 x 2.30, Piranha 6x6
    // 6.25 x 2.50 x 2.30, Patria Pasi 7.50 x 2.95 x 2.30.
    {BodyStyle::kApc6x6, Family::kApc, "apc-6x6", 5, {5.95, 7.50}, {2.48, 2.98}, {2.05, 2.90}},
    // Cougar 4x4 5.91 x 2.74 x 2.64, Dingo 2 6.08 x 2.39 x 2.50, BRDM-2
    // 5.75 x 2.35 x 2.31, Fennek 5.58 x 2.55 x 1.79, MaxxPro 6.45 x 2.53 x 3.05.
    {BodyStyle::kApc4x4, Family::kApc, "apc-4x4", 6, {5.50, 6.50}, {2.35, 2.75}, {1.90, 2.90}},
    // Nissan Juke 4.21 x 1.80 x 1.59, VW T-Roc 4.23 x 1.82 x 1.57, Toyota
    // C-HR (hybrid) 4.36 x 1.80 x 1.56, Nissan Qashqai 4.43 x 1.84 x 1.63,
    // Hyundai Tucson 4.50 x 1.87 x 1.65, VW Tiguan 4.51 x 1.84 x 1.67.
    {BodyStyle::kCrossover, Family::kSuv, "crossover", 9, {4.10, 4.60}, {1.76, 1.88}, {1.53, 1.70}},
    // Toyota RAV4 4.60 x 1.86 x 1.69, Volvo XC90 4.95 x 1.96 x 1.78, BMW X5
    // 4.92 x 2.00 x 1.75, Audi Q7 5.06 x 1.97 x 1.74, Toyota Land Cruiser
    // 4.84 x 1.89 x 1.85, Range Rover 5.00 x 2.05 x 1.87, Chevrolet Tahoe
    // 5.35 x 2.06 x 1.93.
    {BodyStyle::kSuv, Family::kSuv, "suv", 7, {4.55, 5.35}, {1.84, 2.06}, {1.65, 1.93}},
    // Suzuki Jimny 3.65 x 1.65 x 1.72, Jeep Wrangler 4.33-4.88 x 1.89 x
    // 1.84, Mercedes G-Class 4.87 x 1.93 x 1.97, Land Rover Defender 110
    // 5.02 x 2.00 x 1.97, Toyota Land Cruiser 70 4.9 x 1.87 x 1.94.
    {BodyStyle::kOffRoader, Family::kSuv, "off-roader", 4, {3.65, 5.00}, {1.65, 2.00}, {1.72, 1.97}},
};

constexpr bool rows_in_enum_order() {
  for (uint32_t k = 0; k < kBodyStyleCount; ++k)
    if (static_cast<uint32_t>(kStyles[k].style) != k) return false;
  return true;
}
static_assert(rows_in_enum_order(), "kStyles lists the body styles in BodyStyle order");

constexpr const char* kFamilyNames[kFamilyCount] = {"sedan",  "van", "truck", "tracked",
                                                    "pickup", "bus", "apc",   "suv"};

// Golden-ratio (Weyl) sequence over a style's members: consecutive ones'
// lengths are far apart in the style's range.
constexpr double kGoldenFraction = 0.6180339887498949;
// Streams of mix_seed, so families, styles and members draw independent numbers.
constexpr uint64_t kLengthStream = 0x1000;
constexpr uint64_t kMemberStream = 0x2000;
constexpr uint64_t kCycleStream = 0x3000;

double lerp(const Range& r, double t) { return r.lo + (r.hi - r.lo) * t; }
double draw(SeededRandom& rng, const Range& r) { return rng.uniform(r.lo, r.hi); }

// The row of a per-style table (the first row when the style has none).
template <typename Row, size_t N>
const Row& row_of(const Row (&table)[N], BodyStyle style) {
  for (const Row& row : table)
    if (row.style == style) return row;
  return table[0];
}

// Slot `slot` of a family's style cycle: the style whose share is furthest
// behind after the slots before it (largest remainder, so every style's
// slots are spread over the cycle), and how many of that style's slots
// come before it.
struct CycleSlot {
  const BodyStyleInfo* style;
  uint32_t rank;
};
CycleSlot cycle_slot(Family family, uint32_t slot) {
  uint32_t given[kBodyStyleCount] = {};
  CycleSlot out{&kStyles[0], 0};
  for (uint32_t q = 0; q <= slot && q < kStyleCycle; ++q) {
    int64_t most_behind = INT64_MIN;
    uint32_t chosen = 0;
    for (uint32_t id = 0; id < kBodyStyleCount; ++id) {
      if (kStyles[id].family != family) continue;
      const int64_t behind = int64_t{q + 1} * kStyles[id].slots - int64_t{kStyleCycle} * given[id];
      if (behind > most_behind) {
        most_behind = behind;
        chosen = id;
      }
    }
    out = {&kStyles[chosen], given[chosen]};
    ++given[chosen];
  }
  return out;
}

// Sedans' tails per style: the boot behind the rear window (m, or a share
// of the length) and the rear window's run (m).
struct SedanRear {
  BodyStyle style;
  Range boot;
  bool boot_is_share;
  Range rear_window;
};
constexpr SedanRear kSedanRears[] = {
    {BodyStyle::kNotchback, {0.17, 0.23}, true, {0.45, 0.70}},
    {BodyStyle::kHatchback, {0.10, 0.16}, false, {0.30, 0.55}},
    {BodyStyle::kFastback, {0.08, 0.12}, true, {0.85, 1.25}},
    {BodyStyle::kEstate, {0.06, 0.10}, false, {0.10, 0.22}},
    {BodyStyle::kCoupe, {0.12, 0.18}, true, {0.70, 1.10}},
};

void draw_sedan(SeededRandom& rng, BodyStyle style, VehicleSpec* s) {
  const double l = s->length;
  const bool coupe = style == BodyStyle::kCoupe;
  s->ground_clearance = coupe ? rng.uniform(0.10, 0.14) : rng.uniform(0.12, 0.17);
  // Bonnet level 0.75-0.95 m; the glasshouse keeps at least 0.42 m.
  s->belt_height = std::min(s->ground_clearance + rng.uniform(0.62, 0.76), s->height - 0.42);
  s->front_length = l * (coupe ? rng.uniform(0.28, 0.34) : rng.uniform(0.22, 0.29));
  s->windscreen_run = coupe ? rng.uniform(0.80, 1.10) : rng.uniform(0.55, 0.85);
  const SedanRear& rear = row_of(kSedanRears, style);
  s->rear_length = draw(rng, rear.boot) * (rear.boot_is_share ? l : 1.0);
  s->rear_window_run = draw(rng, rear.rear_window);
  s->tumblehome = rng.uniform(0.10, 0.20);
  s->wheel_radius = rng.uniform(0.28, 0.34);
  s->wheel_width = rng.uniform(0.18, 0.24);
  s->axle_spacing = l * (coupe ? rng.uniform(0.53, 0.58) : rng.uniform(0.56, 0.63));
  s->axle_shift = rng.uniform(0.0, 0.12);
  s->roof_rack = !coupe && rng.chance(style == BodyStyle::kEstate ? 0.5 : 0.2);
  s->spoiler = (style == BodyStyle::kNotchback || coupe) && rng.chance(0.3);
}

// Two-box bodies: MPVs and vans (short bonnet, tall cabin) and SUVs
// (longer bonnet, higher belt line). Per style: ground clearance, the belt
// line's rise above it, bonnet, windscreen and rear window runs,
// tumblehome, wheel radius, wheelbase as a share of the length (m), and the
// odds of a roof rack and of a spare wheel on the tailgate.
struct TwoBoxRanges {
  BodyStyle style;
  Range clearance, belt_rise, bonnet, windscreen, rear_window, tumblehome, wheel_radius, wheelbase;
  double roof_rack_odds;
  double spare_wheel_odds;
};
constexpr TwoBoxRanges kTwoBox[] = {
    {BodyStyle::kMpv,
     {0.14, 0.19},
     {0.74, 0.88},
     {0.75, 1.05},
     {0.85, 1.25},
     {0.10, 0.25},
     {0.08, 0.15},
     {0.31, 0.35},
     {0.59, 0.64},
     0.3,
     0.0},
    {BodyStyle::kMidVan,
     {0.17, 0.22},
     {0.84, 0.95},
     {0.70, 0.95},
     {0.55, 0.85},
     {0.03, 0.10},
     {0.06, 0.10},
     {0.33, 0.36},
     {0.58, 0.65},
     0.3,
     0.0},
    {BodyStyle::kHighRoofVan,
     {0.18, 0.24},
     {0.90, 1.05},
     {0.75, 1.05},
     {0.45, 0.75},
     {0.02, 0.06},
     {0.04, 0.10},
     {0.34, 0.38},
     {0.56, 0.63},
     0.2,
     0.0},
    {BodyStyle::kCrossover,
     {0.17, 0.21},
     {0.74, 0.84},
     {0.95, 1.20},
     {0.70, 0.95},
     {0.30, 0.55},
     {0.12, 0.18},
     {0.33, 0.37},
     {0.58, 0.63},
     0.4,
     0.0},
    {BodyStyle::kSuv,
     {0.19, 0.23},
     {0.80, 0.92},
     {1.05, 1.35},
     {0.60, 0.85},
     {0.12, 0.30},
     {0.10, 0.16},
     {0.35, 0.40},
     {0.57, 0.61},
     0.5,
     0.0},
    {BodyStyle::kOffRoader,
     {0.21, 0.27},
     {0.80, 0.92},
     {0.95, 1.40},
     {0.30, 0.50},
     {0.02, 0.08},
     {0.06, 0.12},
     {0.37, 0.42},
     {0.55, 0.60},
     0.5,
     0.6},
};
// The glasshouse of a two-box body keeps at least this height (m).
constexpr double kMinTwoBoxGlasshouse = 0.45;

void draw_two_box(SeededRandom& rng, BodyStyle style, VehicleSpec* s) {
  const TwoBoxRanges* r = &row_of(kTwoBox, style);
  s->ground_clearance = draw(rng, r->clearance);
  s->belt_height = std::min(s->ground_clearance + draw(rng, r->belt_rise), s->height - kMinTwoBoxGlasshouse);
  s->front_length = draw(rng, r->bonnet);
  s->windscreen_run = draw(rng, r->windscreen);
  s->rear_window_run = draw(rng, r->rear_window);
  s->tumblehome = draw(rng, r->tumblehome);
  s->wheel_radius = draw(rng, r->wheel_radius);
  s->axle_spacing = s->length * draw(rng, r->wheelbase);
  s->roof_rack = rng.chance(r->roof_rack_odds);
  s->spare_wheel = rng.chance(r->spare_wheel_odds);
  s->wheel_width = rng.uniform(0.20, 0.27);
  s->axle_shift = rng.uniform(-0.05, 0.10);
}

void draw_pickup(SeededRandom& rng, BodyStyle style, VehicleSpec* s) {
  const bool full = style == BodyStyle::kFullPickup;
  s->ground_clearance = rng.uniform(0.22, 0.30);
  s->belt_height = s->ground_clearance + (full ? rng.uniform(0.85, 0.98) : rng.uniform(0.80, 0.92));
  s->front_length = full ? rng.uniform(1.60, 1.90) : rng.uniform(1.35, 1.70);
  // Cab: single, extended or crew; the bed keeps at least 1.35 m.
  const double cab = rng.uniform01();
  s->cabin_length =
      cab < 0.25 ? rng.uniform(1.55, 1.80) : (cab < 0.45 ? rng.uniform(1.95, 2.20) : rng.uniform(2.30, 2.70));
  s->cabin_length = std::min(s->cabin_length, s->length - s->front_length - 1.35);
  s->rear_length = s->length - s->front_length - s->cabin_length;  // bed
  s->windscreen_run = rng.uniform(0.45, 0.70);
  s->rear_window_run = rng.uniform(0.05, 0.15);
  s->tumblehome = rng.uniform(0.08, 0.15);
  s->wheel_radius = full ? rng.uniform(0.39, 0.43) : rng.uniform(0.37, 0.41);
  s->wheel_width = rng.uniform(0.24, 0.30);
  s->axle_spacing = s->length * rng.uniform(0.58, 0.63);
  s->axle_shift = rng.uniform(0.0, 0.15);
  const double bed = rng.uniform01();
  s->bed_cover = bed < 0.25;
  s->canopy = bed >= 0.25 && bed < 0.40;
  s->roof_rack = rng.chance(0.2);
}

void draw_truck(SeededRandom& rng, BodyStyle style, VehicleSpec* s) {
  const double overall = s->height;
  switch (style) {
    case BodyStyle::kLightTruck:
      s->cab_height = std::min(overall, rng.uniform(2.20, 2.45));
      s->front_length = rng.uniform(1.45, 1.75);
      s->ground_clearance = rng.uniform(0.20, 0.28);
      s->wheel_radius = rng.uniform(0.35, 0.40);
      s->rear_length = rng.uniform(0.9, 1.7);
      s->flatbed = rng.chance(0.45);
      s->axles = 2;
      break;
    case BodyStyle::kRigidTruck:
      s->cab_height = std::min(overall, rng.uniform(2.70, 3.30));
      s->front_length = rng.uniform(1.70, 2.20);
      s->ground_clearance = rng.uniform(0.30, 0.40);
      s->wheel_radius = rng.uniform(0.47, 0.53);
      s->rear_length = rng.uniform(1.6, 2.8);
      s->flatbed = rng.chance(0.3);
      s->axles = (s->length > 9.0 && rng.chance(0.5)) ? 3 : 2;
      break;
    case BodyStyle::kTractorUnit:
      s->cab_height = overall;
      s->front_length = rng.uniform(2.10, 2.40);
      s->ground_clearance = rng.uniform(0.30, 0.38);
      s->wheel_radius = rng.uniform(0.50, 0.53);
      s->rear_length = rng.uniform(0.6, 1.0);
      s->axles = rng.chance(0.3) ? 3 : 2;
      break;
    default:  // tipper
      s->cab_height = std::min(overall, rng.uniform(2.90, 3.20));
      s->front_length = rng.uniform(1.70, 2.00);
      s->ground_clearance = rng.uniform(0.35, 0.45);
      s->wheel_radius = rng.uniform(0.50, 0.55);
      s->rear_length = rng.uniform(1.0, 1.5);
      s->axles = s->length > 7.5 ? 3 : 2;
      break;
  }
  // The load reaches the overall height unless the cab is the highest
  // part (flatbeds, tractor units): then the overall height is the cab's.
  s->rear_height = overall;
  if (s->flatbed || style == BodyStyle::kTractorUnit) s->height = s->cab_height;
  s->belt_height = s->ground_clearance + rng.uniform(0.40, 0.50) * (s->cab_height - s->ground_clearance);
  s->windscreen_run = rng.uniform(0.15, 0.40);
  s->wheel_width = rng.uniform(0.28, 0.36);
  s->axle_spacing = rng.uniform(1.25, 1.40);  // tandem spacing
  s->spare_wheel = rng.chance(0.35);          // behind the cab
}

// Buses per style: ground clearance, front and rear overhangs,
// windscreen run, wheel radius (m), the odds of a roof air-conditioning unit.
struct BusRanges {
  BodyStyle style;
  Range clearance, front_overhang, rear_overhang, windscreen, wheel_radius;
  double roof_unit_odds;
};
constexpr BusRanges kBuses[] = {
    {BodyStyle::kMidibus, {0.28, 0.35}, {2.0, 2.5}, {2.2, 2.9}, {0.15, 0.35}, {0.44, 0.48}, 0.5},
    {BodyStyle::kCityBus, {0.28, 0.34}, {2.6, 2.9}, {3.2, 3.8}, {0.10, 0.25}, {0.48, 0.52}, 0.7},
    {BodyStyle::kCoach, {0.33, 0.42}, {2.4, 2.8}, {2.8, 3.5}, {0.25, 0.45}, {0.50, 0.53}, 0.3},
};

void draw_bus(SeededRandom& rng, BodyStyle style, VehicleSpec* s) {
  const BusRanges& r = row_of(kBuses, style);
  s->ground_clearance = draw(rng, r.clearance);
  s->front_length = draw(rng, r.front_overhang);
  s->rear_length = draw(rng, r.rear_overhang);
  s->windscreen_run = draw(rng, r.windscreen);
  s->wheel_radius = draw(rng, r.wheel_radius);
  s->roof_rack = rng.chance(r.roof_unit_odds);
  s->wheel_width = rng.uniform(0.28, 0.32);
  s->axles = (s->length > 12.0 && rng.chance(0.4)) ? 3 : 2;
  s->axle_spacing = rng.uniform(1.3, 1.45);
}

// Tracked vehicles per style: ground clearance, the turret's height (a
// carrier's casemate rise), glacis run, track width, and the turret: its
// length, width (and the hull margin it keeps), centre along x, the odds
// of a gun and its length (m). A carrier has no turret; its casemate
// reaches forward to turret_x.
struct TrackedRanges {
  BodyStyle style;
  Range clearance, turret_height, glacis, track_width;
  bool turret;
  Range turret_length, turret_width;
  double turret_margin;
  Range turret_x;
  double barrel_odds;
  Range barrel_length;
};
constexpr TrackedRanges kTracked[] = {
    {BodyStyle::kMainBattleTank,
     {0.43, 0.50},
     {0.60, 0.90},
     {1.2, 1.8},
     {0.55, 0.70},
     true,
     {2.8, 3.8},
     {2.2, 3.1},
     0.5,
     {-0.6, 0.4},
     1.0,
     {4.0, 5.8}},
    {BodyStyle::kIfv,
     {0.40, 0.48},
     {0.55, 0.85},
     {1.0, 1.6},
     {0.45, 0.55},
     true,
     {1.6, 2.4},
     {1.4, 2.0},
     0.6,
     {-0.3, 0.6},
     0.95,
     {2.0, 3.2}},
    {BodyStyle::kTrackedCarrier,
     {0.38, 0.45},
     {0.15, 0.45},
     {0.8, 1.4},
     {0.38, 0.50},
     false,
     {0, 0},
     {0, 0},
     0.0,
     {-0.8, 0.6},
     0.0,
     {0, 0}},
    {BodyStyle::kSelfPropelledGun,
     {0.40, 0.48},
     {1.10, 1.50},
     {1.0, 1.5},
     {0.50, 0.65},
     true,
     {3.0, 4.2},
     {2.6, 3.2},
     0.4,
     {-1.5, -0.5},
     1.0,
     {4.5, 7.0}},
};

void draw_tracked(SeededRandom& rng, BodyStyle style, VehicleSpec* s) {
  const TrackedRanges& r = row_of(kTracked, style);
  const double overall = s->height;
  s->axles = 0;
  s->ground_clearance = draw(rng, r.clearance);
  s->turret_height = draw(rng, r.turret_height);
  s->front_length = draw(rng, r.glacis);
  s->track_width = draw(rng, r.track_width);
  s->turret = r.turret;
  if (r.turret) {
    s->turret_length = draw(rng, r.turret_length);
    s->turret_width = std::fmin(draw(rng, r.turret_width), s->width - r.turret_margin);
    s->turret_x = draw(rng, r.turret_x);
    s->barrel = r.barrel_odds >= 1.0 || rng.chance(r.barrel_odds);
    s->barrel_length = draw(rng, r.barrel_length);
  } else {
    s->turret_x = draw(rng, r.turret_x);
  }
  s->belt_height = overall - s->turret_height;  // hull top
  // Without a turret: a casemate superstructure up to rear_height.
  s->rear_height = overall;
}

// Wheeled APCs per style: ground clearance, wheel radius, axles and their
// spacing (the wheelbase for two), glacis run (m), the odds of a turret.
struct ApcRanges {
  BodyStyle style;
  Range clearance, wheel_radius;
  uint32_t axles;
  Range axle_spacing, glacis;
  double turret_odds;
};
constexpr ApcRanges kApcs[] = {
    {BodyStyle::kApc8x8, {0.45, 0.55}, {0.55, 0.62}, 4, {1.40, 1.75}, {1.0, 1.6}, 0.6},
    {BodyStyle::kApc6x6, {0.40, 0.50}, {0.50, 0.58}, 3, {1.35, 1.90}, {1.0, 1.6}, 0.5},
    {BodyStyle::kApc4x4, {0.40, 0.50}, {0.50, 0.60}, 2, {3.0, 3.9}, {1.2, 1.8}, 0.4},
};

void draw_apc(SeededRandom& rng, BodyStyle style, VehicleSpec* s) {
  const ApcRanges& r = row_of(kApcs, style);
  const double overall = s->height;
  s->ground_clearance = draw(rng, r.clearance);
  s->wheel_radius = draw(rng, r.wheel_radius);
  s->axles = r.axles;
  s->axle_spacing = draw(rng, r.axle_spacing);
  s->front_length = draw(rng, r.glacis);
  s->turret = rng.chance(r.turret_odds);
  s->wheel_width = rng.uniform(0.36, 0.44);
  s->axle_shift = rng.uniform(-0.3, 0.1);
  s->turret_length = rng.uniform(1.2, 1.7);
  s->turret_width = rng.uniform(1.1, 1.5);
  s->turret_height = s->turret ? rng.uniform(0.45, 0.70) : 0.0;
  s->turret_x = rng.uniform(-0.6, 0.4);
  s->barrel = s->turret;
  s->barrel_length = rng.uniform(1.8, 2.6);
  // The hull keeps at least 1.7 m; the turret sits on it.
  s->belt_height = std::fmax(overall - s->turret_height, 1.7);
  s->height = s->belt_height + s->turret_height;
}

}  // namespace

const BodyStyleInfo& body_style_info(BodyStyle style) {
  const auto id = static_cast<uint32_t>(style);
  return kStyles[id < kBodyStyleCount ? id : 0];
}

const char* family_name(Family family) {
  const auto id = static_cast<uint32_t>(family);
  return id < kFamilyCount ? kFamilyNames[id] : "unknown";
}

bool parse_family(const std::string& name, Family* family) {
  for (uint32_t id = 0; id < kFamilyCount; ++id) {
    if (name == kFamilyNames[id]) {
      if (family) *family = static_cast<Family>(id);
      return true;
    }
  }
  return false;
}

VehicleSpec make_vehicle_spec(Family family, uint32_t index, uint64_t seed) {
  const auto family_id = static_cast<uint64_t>(family);
  const uint64_t family_seed = mix_seed(seed, family_id);
  // The member's place in the style cycle (from a seed's offset), its
  // style, and its rank among the members of that style.
  const uint64_t place = index + SeededRandom(mix_seed(family_seed, kCycleStream)).below(kStyleCycle);
  const CycleSlot slot = cycle_slot(family, static_cast<uint32_t>(place % kStyleCycle));
  const BodyStyleInfo& row = *slot.style;
  const uint64_t rank = (place / kStyleCycle) * row.slots + slot.rank;
  SeededRandom start_rng(mix_seed(family_seed, kLengthStream + static_cast<uint64_t>(row.style)));
  double t = start_rng.uniform01() + kGoldenFraction * static_cast<double>(rank);
  t -= std::floor(t);
  SeededRandom rng(mix_seed(mix_seed(family_seed, kMemberStream), index));

  VehicleSpec spec;
  spec.family = family;
  spec.style = row.style;
  spec.index = index;
  char name[64];
  std::snprintf(name, sizeof name, "%s-%02u", family_name(family), index);
  spec.name = name;
  spec.length = lerp(row.length, t);
  spec.width = draw(rng, row.width);
  spec.height = draw(rng, row.height);
  switch (family) {
    case Family::kSedan: draw_sedan(rng, row.style, &spec); break;
    case Family::kVan:
    case Family::kSuv: draw_two_box(rng, row.style, &spec); break;
    case Family::kTruck: draw_truck(rng, row.style, &spec); break;
    case Family::kTracked: draw_tracked(rng, row.style, &spec); break;
    case Family::kPickup: draw_pickup(rng, row.style, &spec); break;
    case Family::kBus: draw_bus(rng, row.style, &spec); break;
    case Family::kApc: draw_apc(rng, row.style, &spec); break;
  }
  return spec;
}

}  // namespace spinhash::host
