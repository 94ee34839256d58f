#include "world_conditions.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/seeded_random.hpp"
#include "query_set.hpp"
#include "scan/scan_simulator.hpp"

namespace spinhash::experiment {
namespace {

constexpr double kGroundMargin = 3.0;  // m of ground beyond the object, as the accuracy experiment's
constexpr double kDegToRad = 0.017453292519943295;

}  // namespace

std::vector<WorldsCondition> worlds_conditions() {
  std::vector<WorldsCondition> out(4);
  out[0].name = "clean";
  out[0].text = "0.10 m, 2 cm noise, no ground";
  out[1].name = "ground";
  out[1].text = "0.10 m, 10 cm noise, 20 % occluded, ground tilted 0-5 degrees";
  out[1].noise = 0.10;
  out[1].occlusion = 0.2;
  out[1].ground = true;
  out[1].max_slope_deg = 5.0;
  out[2] = out[1];
  out[2].name = "no-ground";
  out[2].text = "0.10 m, 10 cm noise, 20 % occluded, vehicle tilted 0-5 degrees, no ground";
  out[2].ground = false;
  out[3].name = "sparse";
  out[3].text = "20-30 points per m^2 of ground, 5 cm noise, ground tilted 0-5 degrees";
  out[3].spacing = 0.0;
  out[3].density_lo = 20.0;
  out[3].density_hi = 30.0;
  out[3].noise = 0.05;
  out[3].ground = true;
  out[3].max_slope_deg = 5.0;
  return out;
}

bool select_conditions(const std::vector<std::string>& names, std::vector<WorldsCondition>* out,
                       std::string* error) {
  const std::vector<WorldsCondition> all = worlds_conditions();
  out->clear();
  for (const WorldsCondition& c : all)
    if (std::find(names.begin(), names.end(), c.name) != names.end()) out->push_back(c);
  for (const std::string& n : names)
    if (std::none_of(all.begin(), all.end(), [&](const WorldsCondition& c) { return c.name == n; })) {
      *error = "unknown condition '" + n + "' (clean, ground, no-ground, sparse)";
      return false;
    }
  if (out->empty()) *error = "no condition given";
  return !out->empty();
}

double ground_density(double spacing) {
  const host::ScanOptions o = host::query_scan_options(0.0, 1);
  return o.views * std::sin(o.elevation_deg * kDegToRad) / (spacing * spacing);
}

double spacing_for_density(double density) { return std::sqrt(ground_density(1.0) / density); }

ScanDraw draw_scan(const WorldsCondition& c, uint32_t condition, uint64_t base_seed, uint32_t object,
                   uint32_t scan) {
  ScanDraw d;
  d.seed = query_seed(base_seed, object, scan);
  host::SeededRandom rng(host::mix_seed(d.seed, condition + 1u));
  d.noise = c.noise;
  d.occlusion = c.occlusion;
  d.ground = c.ground;
  d.slope_deg = rng.uniform(0.0, c.max_slope_deg);
  d.spacing = c.spacing > 0.0 ? c.spacing : spacing_for_density(rng.uniform(c.density_lo, c.density_hi));
  d.density = ground_density(d.spacing);
  return d;
}

bool scan_object(const host::Mesh& mesh, double ground_z, const ScanDraw& d, ObjectScan* out,
                 std::string* error) {
  QueryScan s;
  s.seed = d.seed;
  s.noise = d.noise;
  s.occlusion = d.occlusion;
  s.spacing = d.spacing;
  s.slope_deg = d.slope_deg;
  s.ground = d.ground;
  s.ground_z = ground_z;
  s.ground_margin = kGroundMargin;
  host::ScanResult scan;
  if (!scan_query(mesh, s, &scan, error)) return false;
  out->object_points = static_cast<uint32_t>(std::count(scan.on_object.begin(), scan.on_object.end(), 1));
  out->xyz = std::move(scan.xyz);
  return true;
}

}  // namespace spinhash::experiment
