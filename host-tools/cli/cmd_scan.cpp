// spinhash scan MESH -o QUERY.ply: the range-sensor simulator of section 10.1.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cloud/cloud_writer.hpp"
#include "mesh/mesh_loader.hpp"
#include "mesh/seeded_random.hpp"
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
  double ground_slope_deg = 0.0;  // ground and vehicle tilted together (the vehicle rests on the slope)
  bool ascii = false;
};

// ASPRS classes in a written LAS: the scanned object and its ground.
constexpr uint8_t kObjectClass = 1, kGroundClass = 2;
constexpr uint64_t kSlopeAxisStream = 0x7000;  // seeds the slope's axis apart from the scan's draws

// The rotation by slope_deg about a horizontal axis through the centre of the
// mesh's base, the axis direction drawn from the seed: the vehicle and its
// ground tilt together, so it rests on the slope (pitch and roll following
// it) whatever its heading. Identity for slope 0.
Eigen::Matrix4d slope_tilt(const host::Mesh& mesh, double slope_deg, uint64_t seed) {
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  if (slope_deg == 0.0) return t;
  host::SeededRandom rng(host::mix_seed(seed, kSlopeAxisStream));
  const double heading = rng.uniform(0.0, 2.0 * M_PI);
  const Eigen::Vector3d axis(std::cos(heading), std::sin(heading), 0.0);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(slope_deg * M_PI / 180.0, axis).toRotationMatrix();
  const host::Box3 box = mesh.bounding_box();
  const Eigen::Vector3d pivot(box.center().x(), box.center().y(), box.lo.z());
  t.topLeftCorner<3, 3>() = r;
  t.topRightCorner<3, 1>() = pivot - r * pivot;
  return t;
}

int run_scan(ScanArgs& a) {
  host::Mesh mesh, ground;
  std::string error;
  if (host::cloud_format_for(a.output) == host::CloudFormat::kUnknown) {
    std::fprintf(stderr, "spinhash scan: %s: unknown point-cloud extension (write .ply or .las)\n",
                 a.output.c_str());
    return kExitError;
  }
  if (a.ground_slope_deg > 0.0 && a.options.random_pose) {
    // The random yaw turns the vehicle but not its ground: it would no longer rest on the slope.
    std::fprintf(stderr, "spinhash scan: --ground-slope cannot be combined with --random-pose\n");
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
  const Eigen::Matrix4d tilt = slope_tilt(mesh, a.ground_slope_deg, a.options.seed);
  mesh.apply_transform(tilt);
  ground.apply_transform(tilt);
  host::ScanResult scan = host::simulate_scan(mesh, a.options);
  scan.true_pose = scan.true_pose * tilt;  // model -> tilted model -> output frame
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
  CLI::App* cmd = app.add_subcommand("scan", "simulate an airborne lidar scan of a mesh (PLY out)");
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
  cmd->add_option("--ground-slope", a->ground_slope_deg,
                  "tilt the ground and the vehicle on it by this many degrees (axis heading from --seed)")
      ->check(CLI::Range(0.0, 45.0))
      ->needs("--ground");
  cmd->add_option("--pose-out", a->pose_output, "write the true model->scan pose (4x4) here");
  cmd->add_flag("--ascii", a->ascii, "ASCII PLY instead of binary");
  cmd->callback([a, exit_code]() { *exit_code = run_scan(*a); });
}

}  // namespace spinhash::cli
