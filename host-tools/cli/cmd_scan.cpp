// spinhash scan MESH -o QUERY.ply: the range-sensor simulator of section 10.1.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cloud/cloud_writer.hpp"
#include "mesh/mesh_loader.hpp"
#include "mesh/vehicle_generator.hpp"
#include "scan/scan_simulator.hpp"

namespace spinhash::cli {
namespace {

struct ScanArgs {
  std::string mesh;
  std::string output;
  std::string pose_output;
  host::ScanOptions options;
  std::vector<double> offset;
  double ground_half_size = 0.0;
  bool ascii = false;
};

// ASPRS classes in a written LAS: the scanned object and its ground.
constexpr uint8_t kObjectClass = 1, kGroundClass = 2;

int run_scan(ScanArgs& a) {
  host::Mesh mesh, ground;
  std::string error;
  if (host::cloud_format_for(a.output) == host::CloudFormat::kUnknown) {
    std::fprintf(stderr, "spinhash scan: %s: unknown point-cloud extension (write .ply or .las)\n",
                 a.output.c_str());
    return kExitError;
  }
  if (!host::load_mesh(a.mesh, &mesh, &error)) {
    std::fprintf(stderr, "spinhash scan: %s: %s\n", a.mesh.c_str(), error.c_str());
    return kExitError;
  }
  for (size_t i = 0; i < a.offset.size() && i < 3; ++i) a.options.offset[i] = a.offset[i];
  if (a.ground_half_size > 0.0) {
    ground = host::make_ground_patch(a.ground_half_size, mesh.bounding_box().lo.z());
    a.options.ground = &ground;
  }
  host::ScanResult scan = host::simulate_scan(mesh, a.options);
  if (!scan.ok()) {
    std::fprintf(stderr, "spinhash scan: %s\n", scan.error.c_str());
    return kExitError;
  }
  std::vector<uint8_t> classes(scan.on_object.size());
  for (size_t i = 0; i < classes.size(); ++i) classes[i] = scan.on_object[i] ? kObjectClass : kGroundClass;
  if (!host::write_cloud(a.output, scan.xyz, classes, a.ascii, &error) ||
      (!a.pose_output.empty() && !host::write_pose(a.pose_output, scan.true_pose, &error))) {
    std::fprintf(stderr, "spinhash scan: %s\n", error.c_str());
    return kExitError;
  }
  std::fprintf(stderr, "spinhash scan: %s: %zu points from %u views\n", a.output.c_str(), scan.size(),
               a.options.views);
  return kExitOk;
}

}  // namespace

void add_scan_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<ScanArgs>();
  host::ScanOptions& o = a->options;
  CLI::App* cmd = app.add_subcommand("scan", "simulate an airborne lidar scan of a mesh (PLY or LAS out)");
  cmd->add_option("mesh", a->mesh, "mesh file")->required();
  cmd->add_option("-o,--output", a->output, "point cloud to write: .ply or .las (ground classified 2)")
      ->required();
  cmd->add_option("--views", o.views, "viewpoints on the hemisphere")
      ->check(CLI::Range(1u, host::kMaxScanViews))
      ->capture_default_str();
  cmd->add_option("--noise", o.noise_sigma, "Gaussian noise along each ray, m")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "seed for azimuth, noise, pose and occluder")->capture_default_str();
  cmd->add_option("--elevation", o.elevation_deg, "viewpoint elevation, degrees")
      ->check(CLI::Range(0.0, 90.0))
      ->capture_default_str();
  cmd->add_option("--azimuth", o.azimuth_start_deg, "first view's azimuth, degrees (default: random)");
  cmd->add_option("--azimuth-step", o.azimuth_step_deg, "azimuth between views, degrees")
      ->capture_default_str();
  cmd->add_option("--spacing", o.point_spacing, "ray spacing at the object, m")
      ->check(CLI::Range(0.005, 1.0))
      ->capture_default_str();
  cmd->add_option("--occlusion", o.occlusion, "fraction of the object hidden by an occluder")
      ->check(CLI::Range(0.0, 0.9))
      ->capture_default_str();
  cmd->add_flag("--random-pose", o.random_pose, "random yaw and position (true pose with --pose-out)");
  cmd->add_flag("--tilt", o.random_tilt, "with --random-pose: small random roll and pitch");
  cmd->add_option("--offset", a->offset, "added to every point, e.g. UTM 500000 4000000 100")->expected(3);
  cmd->add_option("--ground", a->ground_half_size, "scan a ground square of this half size (m) too")
      ->check(CLI::Range(0.0, 1000.0));
  cmd->add_option("--ground-slope", o.ground_slope_deg,
                  "with --ground: terrain slope, degrees; the vehicle rests on it (random direction)")
      ->check(CLI::Range(0.0, host::kMaxGroundSlopeDeg))
      ->capture_default_str();
  cmd->add_option("--pose-out", a->pose_output, "write the true model->scan pose (4x4) here");
  cmd->add_flag("--ascii", a->ascii, "ASCII PLY instead of binary");
  cmd->callback([a, exit_code]() { *exit_code = run_scan(*a); });
}

}  // namespace spinhash::cli
