#include "scan/scan_simulator.hpp"

#include "mesh/seeded_random.hpp"
#include "scan/occluder.hpp"
#include "scan/ray_caster.hpp"
#include "scan/ray_grid.hpp"
#include "util/angles.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <exception>

namespace spinhash::host {
namespace {

// Independent random streams of one seed (mix_seed), so e.g. changing the
// noise leaves the pose and the azimuth unchanged.
constexpr uint64_t kPoseStream = 1;
constexpr uint64_t kAzimuthStream = 2;
constexpr uint64_t kNoiseStream = 3;
constexpr uint64_t kOcclusionStream = 4;
constexpr uint64_t kSlopeStream = 5;
constexpr int32_t kObjectGeometry = 0;

// Rigid pose of the object: rotation about the model origin, then translation.
Eigen::Matrix4d draw_pose(const ScanOptions& o) {
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  if (!o.random_pose) return pose;
  SeededRandom rng(mix_seed(o.seed, kPoseStream));
  const double yaw = rng.uniform(0.0, 2.0 * kPi);
  const double tilt = o.random_tilt ? kMaxTiltDeg * kDegToRad : 0.0;
  const double roll = rng.uniform(-tilt, tilt);
  const double pitch = rng.uniform(-tilt, tilt);
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  pose.topLeftCorner<3, 3>() = r;
  for (int k = 0; k < 3; ++k) {
    pose(k, 3) = rng.uniform(-kPoseTranslationRange, kPoseTranslationRange);
  }
  return pose;
}

// Terrain slope: a tilt about a horizontal axis of random direction.
Eigen::Matrix3d slope_rotation(const ScanOptions& o) {
  if (!(o.ground_slope_deg > 0.0)) return Eigen::Matrix3d::Identity();
  SeededRandom rng(mix_seed(o.seed, kSlopeStream));
  const double azimuth = rng.uniform(0.0, 2.0 * kPi);
  const Eigen::Vector3d axis(std::cos(azimuth), std::sin(azimuth), 0.0);
  return Eigen::AngleAxisd(o.ground_slope_deg * kDegToRad, axis).toRotationMatrix();
}

// State shared by the views of one scan, in the "local" frame: the posed
// object's centre at the origin, axes of the output frame.
struct ScanContext {
  const ScanOptions* options = nullptr;
  RayCaster caster;
  double distance = 0.0;  // sensor to object centre
  RayGrid grid;
  SeededRandom noise{0};
};

// Casts one view and appends its hits.
bool scan_view(ScanContext* ctx, const View& view, ScanResult* out) {
  std::vector<int32_t> geometry;
  const int64_t kept = cast_view(ctx->caster, view, ctx->grid, ctx->options->noise_sigma, &ctx->noise,
                                 &out->xyz, &geometry, &out->error);
  if (kept < 0) return false;
  for (int32_t g : geometry) out->on_object.push_back(g == kObjectGeometry ? 1 : 0);
  out->view_points.push_back(static_cast<uint32_t>(kept));
  return true;
}

// Sizes the ray grid so neighbouring rays are point_spacing apart at the
// object's distance and the grid covers the bounding sphere.
bool plan_grid(ScanContext* ctx, double radius, std::string* error) {
  const ScanOptions& o = *ctx->options;
  const double half_angle = kSensorHalfFovDeg * kDegToRad;
  ctx->distance = radius / std::sin(half_angle);
  std::string why;
  if (!plan_ray_grid(half_angle, o.point_spacing / ctx->distance, o.views, &ctx->grid, &why)) {
    *error = "point spacing " + std::to_string(o.point_spacing) + " m is too fine for an object of radius " +
             std::to_string(radius) + " m: " + why;
    return false;
  }
  return true;
}

// Drops occluded points (xyz and on_object in step). view_points keep the
// counts before occlusion: they describe what the sensor returned.
void occlude(const ScanOptions& o, ScanResult* out) {
  if (o.occlusion <= 0.0) return;
  SeededRandom rng(mix_seed(o.seed, kOcclusionStream));
  std::vector<uint8_t> keep;
  apply_slab_occluder(out->xyz, out->on_object, o.occlusion, &rng, &keep);
  std::size_t w = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (!keep[i]) continue;
    for (int k = 0; k < 3; ++k) out->xyz[3 * w + k] = out->xyz[3 * i + k];
    out->on_object[w] = out->on_object[i];
    ++w;
  }
  out->xyz.resize(3 * w);
  out->on_object.resize(w);
}

ScanResult run_scan(const Mesh& model, const ScanOptions& o) {
  ScanResult out;
  out.error = validate_scan_options(o);
  if (out.error.empty()) out.error = model.validate();
  if (out.error.empty() && model.triangle_count() == 0) out.error = "model has no triangles";
  if (out.error.empty() && o.ground) out.error = o.ground->validate();
  if (!out.error.empty()) return out;

  // Local frame: the posed object's bounding-box centre at the origin; the
  // float scene then stays precise whatever the pose and offset.
  Eigen::Matrix4d pose = draw_pose(o);
  const Eigen::Matrix3d slope = slope_rotation(o);
  pose.topLeftCorner<3, 3>() = slope * pose.topLeftCorner<3, 3>();
  const Eigen::Matrix3d rotation = pose.topLeftCorner<3, 3>();
  const Eigen::Vector3d model_center = model.bounding_box().center();
  Eigen::Matrix4d to_local = Eigen::Matrix4d::Identity();
  to_local.topLeftCorner<3, 3>() = rotation;
  to_local.topRightCorner<3, 1>() = -rotation * model_center;
  Mesh local = model;
  local.apply_transform(to_local);
  double radius = 0.0;
  for (std::size_t i = 0; i < local.vertex_count(); ++i) {
    radius = std::max(radius, local.vertex(i).norm());
  }
  if (!(radius > 0.0)) {
    out.error = "model has no extent";
    return out;
  }

  ScanContext ctx;
  ctx.options = &o;
  ctx.noise = SeededRandom(mix_seed(o.seed, kNoiseStream));
  if (!plan_grid(&ctx, radius, &out.error)) return out;
  if (!ctx.caster.add_mesh(local, Eigen::Vector3d::Zero(), &out.error)) return out;
  if (o.ground) {
    // Ground is translated with the object and tilted by the slope, never
    // turned with its yaw: the object rests on it either way.
    Mesh ground = *o.ground;
    Eigen::Matrix4d shift = Eigen::Matrix4d::Identity();
    shift.topLeftCorner<3, 3>() = slope;
    shift.topRightCorner<3, 1>() = -rotation * model_center;
    ground.apply_transform(shift);
    if (!ctx.caster.add_mesh(ground, Eigen::Vector3d::Zero(), &out.error)) return out;
  }
  if (!ctx.caster.commit(&out.error)) return out;

  double azimuth0 = o.azimuth_start_deg;
  if (std::isnan(azimuth0)) {
    azimuth0 = SeededRandom(mix_seed(o.seed, kAzimuthStream)).uniform(0.0, 360.0);
  }
  const Eigen::Vector3d center = pose.topRightCorner<3, 1>() + rotation * model_center;
  const Eigen::Vector3d offset(o.offset[0], o.offset[1], o.offset[2]);
  for (uint32_t k = 0; k < o.views; ++k) {
    const double azimuth = (azimuth0 + k * o.azimuth_step_deg) * kDegToRad;
    const View view = make_view(azimuth, o.elevation_deg * kDegToRad, ctx.distance);
    if (!scan_view(&ctx, view, &out)) return out;
    out.viewpoints.push_back(view.origin + center + offset);
  }
  occlude(o, &out);
  // Local -> output frame, in double.
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (int k = 0; k < 3; ++k) out.xyz[3 * i + k] += center[k] + offset[k];
  }
  out.true_pose = pose;
  out.true_pose.topRightCorner<3, 1>() += offset;
  return out;
}

}  // namespace

ScanResult simulate_scan(const Mesh& model, const ScanOptions& options) {
  ScanResult result;
  try {
    result = run_scan(model, options);
  } catch (const std::exception& e) {
    result.error = std::string("scan failed: ") + e.what();
  }
  if (!result.ok()) {
    // No partial clouds: a failed scan returns only its error.
    const std::string error = result.error;
    result = ScanResult{};
    result.error = error;
  }
  return result;
}

}  // namespace spinhash::host
