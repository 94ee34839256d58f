#include "query_set.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scan/ground_square.hpp"
#include "scan/scan_simulator.hpp"

namespace spinhash::experiment {
namespace {

constexpr uint64_t kModelSeedStride = 1000003;  // prime: (model, q) pairs never share a seed
constexpr uint64_t kQuerySeedStride = 7919;

}  // namespace

const char* ground_name(Ground g) {
  return g == Ground::kNone ? "none" : g == Ground::kScanned ? "scanned" : "kept";
}

std::string QueryCondition::label() const {
  std::ostringstream s;
  s << "noise" << noise << "_occ" << occlusion
    << (ground == Ground::kScanned ? "_ground"
        : ground == Ground::kKept  ? "_ground_kept"
                                   : "");
  if (spacing != kPaperQuerySpacing) s << "_sp" << spacing;
  if (slope_deg > 0.0) s << "_slope" << slope_deg;
  return s.str();
}

uint64_t query_seed(uint64_t base_seed, uint32_t model, uint32_t q) {
  return base_seed * kModelSeedStride * kQuerySeedStride + model * kQuerySeedStride + q + 1u;
}

bool scan_query(const host::Mesh& mesh, const QueryScan& s, host::ScanResult* out, std::string* error) {
  host::ScanOptions opt = host::query_scan_options(s.noise, s.seed);
  opt.random_pose = true;
  opt.occlusion = s.occlusion;
  opt.point_spacing = s.spacing;
  opt.ground_slope_deg = s.slope_deg;
  host::Mesh ground;
  if (s.ground) {
    ground = host::ground_square_around(mesh, s.ground_margin, s.ground_z);
    opt.ground = &ground;
  }
  *out = host::simulate_scan(mesh, opt);
  if (!out->ok()) {
    *error = mesh.name + ": query scan: " + out->error;
    return false;
  }
  return true;
}

bool simulate_query(const host::Mesh& mesh, uint32_t model, uint32_t q, const QueryCondition& c,
                    uint64_t base_seed, double ground_margin, Query* out, std::string* error) {
  out->model = model;
  out->index = q;
  out->seed = query_seed(base_seed, model, q);
  QueryScan s;
  s.seed = out->seed;
  s.noise = c.noise;
  s.occlusion = c.occlusion;
  s.spacing = c.spacing;
  s.ground = c.ground != Ground::kNone;
  s.slope_deg = s.ground ? c.slope_deg : 0.0;
  s.ground_z = mesh.bounding_box().lo.z();
  s.ground_margin = ground_margin;
  host::ScanResult scan;
  if (!scan_query(mesh, s, &scan, error)) return false;
  out->object_points = static_cast<uint32_t>(std::count(scan.on_object.begin(), scan.on_object.end(), 1));
  out->xyz = std::move(scan.xyz);
  out->true_pose = scan.true_pose;
  return true;
}

std::vector<QueryCondition> make_conditions(const std::vector<double>& noise,
                                            const std::vector<double>& occlusion,
                                            const std::vector<double>& spacing,
                                            const std::vector<double>& slopes, bool with_ground,
                                            bool with_kept) {
  std::vector<QueryCondition> out;
  const std::vector<double> level{0.0};
  for (Ground g : {Ground::kNone, Ground::kScanned, Ground::kKept}) {
    if ((g == Ground::kScanned && !with_ground) || (g == Ground::kKept && !with_kept)) continue;
    for (double sl : g == Ground::kNone ? level : slopes)
      for (double sp : spacing)
        for (double n : noise)
          for (double o : occlusion) out.push_back(QueryCondition{n, o, g, sp, sl});
  }
  return out;
}

}  // namespace spinhash::experiment
