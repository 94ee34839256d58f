// The paper's range-sensor simulator (section 10.1): views on a hemisphere
// around the object, each aimed at its centre; rays on a regular angular
// grid; Gaussian noise along each ray; views merged into one cloud.
#pragma once

#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace spinhash::host {

// Bounds that keep a bad option from exhausting memory or time.
constexpr uint32_t kMaxScanViews = 360;
constexpr uint64_t kMaxRaysPerView = 4000000;   // a 2000 x 2000 grid
constexpr uint64_t kMaxRaysPerScan = 16000000;  // all views together
// Half-angle of the sensor's view cone: the sensor stands at the distance
// where the object's bounding sphere fills it.
constexpr double kSensorHalfFovDeg = 15.0;
// random_pose: translation uniform in +-kPoseTranslationRange on each axis,
// roll and pitch (with random_tilt) uniform in +-kMaxTiltDeg.
constexpr double kPoseTranslationRange = 50.0;
constexpr double kMaxTiltDeg = 5.0;
constexpr double kMaxGroundSlopeDeg = 30.0;

struct ScanOptions {
  uint32_t views = 3;
  double elevation_deg = 45.0;  // above the horizon, in [0, 90]
  // First view's azimuth; NaN draws it uniformly in [0, 360) from the seed.
  double azimuth_start_deg = std::numeric_limits<double>::quiet_NaN();
  // Query: 3 views 45 degrees apart see 2-3 sides and the top. Model
  // database (paper): 8 views, step 45, elevation 45.
  double azimuth_step_deg = 45.0;
  double noise_sigma = 0.0;     // m, Gaussian along each ray (paper: 0.05, 0.10)
  double point_spacing = 0.05;  // m between neighbouring rays at the object
  uint64_t seed = 1;
  // Fraction of the object's points hidden by an occluder: the points inside
  // a random vertical slab (a wall or tree trunk) holding that fraction are
  // dropped; ground points are kept. In [0, 1), deterministic from the seed.
  double occlusion = 0.0;
  // Random rigid pose applied to the object before scanning: yaw uniform in
  // [0, 360), translation uniform in +-kPoseTranslationRange per axis.
  bool random_pose = false;
  bool random_tilt = false;  // with random_pose: small random roll and pitch
  // Added to every point and to the true pose translation (georeferenced
  // output, e.g. UTM 500000 4000000 100).
  double offset[3] = {0.0, 0.0, 0.0};
  // Extra geometry scanned with the object (e.g. make_ground_patch), in the
  // object's frame. random_pose translates it with the object but never
  // rotates it, so ground stays level under the vehicle.
  const Mesh* ground = nullptr;
  // Terrain slope (degrees, at most kMaxGroundSlopeDeg): the ground and the
  // object resting on it are tilted together about a horizontal axis of
  // random direction (from the seed), so the vehicle's pitch and roll follow
  // the ground. Part of the true pose.
  double ground_slope_deg = 0.0;
};

struct ScanResult {
  std::vector<double> xyz;                                  // x y z per point, output frame
  std::vector<uint8_t> on_object;                           // per point: 1 object, 0 ground
  std::vector<uint32_t> view_points;                        // points kept from each view
  Eigen::Matrix4d true_pose = Eigen::Matrix4d::Identity();  // model -> output frame
  std::vector<Eigen::Vector3d> viewpoints;                  // sensor positions, output frame
  std::string error;                                        // empty on success
  bool ok() const { return error.empty(); }
  std::size_t size() const { return xyz.size() / 3; }
};

ScanResult simulate_scan(const Mesh& model, const ScanOptions& options);

// Paper's model database scan: 8 views, elevation 45, azimuth 0, 45, ...,
// no noise.
ScanOptions model_scan_options();
// Paper's query scan: 3 views 45 degrees apart from a random azimuth.
ScanOptions query_scan_options(double noise_sigma, uint64_t seed);

// Empty string if the options are usable; else what is wrong.
std::string validate_scan_options(const ScanOptions& options);

}  // namespace spinhash::host
