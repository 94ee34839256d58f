// The scans `spinhash build` calibrates the answer levels on (issue of the
// database's own models): each vehicle and each piece of clutter scanned
// under conditions drawn from the ranges an airborne survey meets, the
// draw deterministic from a seed.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace spinhash::calib {

// Ranges of the draws. Ray spacing at the object 0.08-0.5 m (log-uniform):
// scan densities (RecognitionStats::scan_density: object points per m^2 of
// the vehicle's top the scan spans) of about 400 down to 10, from a low
// corridor flight to a national survey, spread about evenly over the
// calibration's bands (the density falls as 2.5 / spacing^2 on the
// procedural fleet's 2-3 view scans).
constexpr double kMinSpacing = 0.08, kMaxSpacing = 0.5;  // m
constexpr double kMinNoise = 0.02, kMaxNoise = 0.10;     // m along the ray
constexpr double kMaxOcclusion = 0.4;                    // share of the object hidden by a slab
constexpr uint32_t kMinViews = 2, kMaxViews = 3;         // overlapping flight lines
// View elevation above the horizon: the scene simulator's oblique views.
constexpr double kMinElevationDeg = 45.0, kMaxElevationDeg = 60.0;
constexpr double kGroundShare = 0.5;   // of the scans that keep the ground around the object
constexpr double kMaxSlopeDeg = 5.0;   // ground tilt (with the ground)
constexpr double kGroundMargin = 3.0;  // m of ground beyond the object's footprint

struct ScanDraw {
  uint64_t seed = 0;  // the scan's own (pose, azimuth, noise, occluder)
  double spacing = 0.1, noise = 0.05, occlusion = 0.0, elevation_deg = 45.0, slope_deg = 0.0;
  uint32_t views = 3;
  bool ground = false;
};

// The draw of scan `index` of object `object` (a model, or a piece of
// clutter past the models) for calibration seed `seed`.
ScanDraw draw_scan(uint64_t seed, uint32_t object, uint32_t index);

// A vehicle (x forward, z up, resting at its lowest z), scanned as drawn:
// a random pose, with the ground square around it when the draw keeps it,
// tilted by the slope. false with *error when the simulator fails.
bool scan_vehicle(const host::Mesh& mesh, const ScanDraw& d, std::vector<double>* xyz, std::string* error);

// The scene simulator's clutter (scene_clutter.cpp): what tiles hold, and
// non-vehicles of a vehicle's size and bulk, whose evidence the vehicle
// levels' thresholds must stay above.
enum class ClutterKind : uint8_t {
  kTree = 0,
  kWall = 1,
  kCrate = 2,
  kBuilding = 3,
  kShed = 4,
  kContainer = 5,
  kBush = 6,
  kHeap = 7,
};
constexpr uint32_t kClutterKinds = 8;
// The kinds a calibration scans in turn, the first of ClutterKind's:
// 4 for blob::kClutterTiles, all 8 for blob::kClutterVehicleSized.
uint32_t clutter_kinds_scanned(uint32_t clutter);
// blob::CalibrationClutter as a word ("tiles", "vehicle-sized": the build's
// --calibration-clutter and `spinhash info`'s JSON), and the kinds it names.
const char* calibration_clutter_word(uint32_t clutter);
const char* calibration_clutter_kinds(uint32_t clutter);
const char* clutter_name(ClutterKind kind);

// A piece of clutter of `kind` drawn from `seed`, standing on level ground
// (its base sunk below it), scanned as drawn: always with the ground (which
// hides the sunk base), whose points are dropped unless the draw keeps them.
bool scan_clutter(ClutterKind kind, const ScanDraw& d, std::vector<double>* xyz, std::string* error);

}  // namespace spinhash::calib
