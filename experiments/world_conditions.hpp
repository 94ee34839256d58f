// The scan conditions of the leave-one-world-out experiment and the
// simulated scans under them: the query simulator's 3 views 45 degrees
// apart at 45 degrees elevation, a random pose, and per condition the ray
// spacing (or the survey density), noise, occlusion and ground.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace spinhash::experiment {

struct WorldsCondition {
  std::string name;                           // "clean", "ground", "no-ground", "sparse"
  std::string text;                           // for the summary
  double spacing = 0.10;                      // m between rays at the object; 0: drawn from the density range
  double density_lo = 0.0, density_hi = 0.0;  // points per m^2 of level ground, all views together
  double noise = 0.02;                        // m along the ray
  double occlusion = 0.0;                     // share of the object hidden by a slab
  bool ground = false;                        // a ground square scanned around the object
  double max_slope_deg = 0.0;                 // the object (and its ground) tilted by up to this
};

// clean: 0.10 m, 2 cm noise, no ground; ground: 0.10 m, 10 cm noise, 20 %
// occluded, the ground tilted by up to 5 degrees; no-ground: the same
// vehicle scans without the ground; sparse: a survey's 20-30 points per m^2
// of ground, 5 cm noise, the ground tilted by up to 5 degrees.
std::vector<WorldsCondition> worlds_conditions();
// The conditions named (comma list of names); false with *error for an unknown one.
bool select_conditions(const std::vector<std::string>& names, std::vector<WorldsCondition>* out,
                       std::string* error);

// Points per m^2 a level surface receives from the query views at ray
// spacing `spacing` (each view: sin(elevation) / spacing^2), and its inverse.
double ground_density(double spacing);
double spacing_for_density(double density);

// One scan's draws: the pose and noise from `seed` (shared by the
// conditions, which differ only in what they change), the slope and the
// density from the condition's own stream.
struct ScanDraw {
  uint64_t seed = 0;
  double spacing = 0.0, noise = 0.0, occlusion = 0.0, slope_deg = 0.0;
  double density = 0.0;  // ground_density(spacing)
  bool ground = false;
};
ScanDraw draw_scan(const WorldsCondition& c, uint32_t condition, uint64_t base_seed, uint32_t object,
                   uint32_t scan);

struct ObjectScan {
  std::vector<double> xyz;
  uint32_t object_points = 0;
};

// Scans `mesh` (x forward, z up) as drawn; with the ground, a level square
// at ground_z reaching kGroundMargin beyond the object on every side.
bool scan_object(const host::Mesh& mesh, double ground_z, const ScanDraw& d, ObjectScan* out,
                 std::string* error);

}  // namespace spinhash::experiment
