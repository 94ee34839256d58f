#include "recognize/class_envelope.hpp"

#include <cmath>

#include "spinhash/vehicle_class.hpp"
#include "util/far.hpp"

namespace spinhash {
namespace {

// The tolerances (ClassesParams):
// - top_noise_sigmas: the highest points of a noisy roof lie above it by up
//   to this many sigma of the noise along the ray (the second highest of a
//   few hundred samples of a Gaussian: 2-3 sigma).
// - model_bottom_gap: a model's box height is its cloud's top above its
//   lowest point, and the model clouds are scanned from 45 degrees
//   (spinhash build): a wheel of radius r shows down to r (1 - sin 45) =
//   0.29 r above the ground. A vehicle's top above the terrain exceeds its
//   model's box height by up to this.
// - top_sampling_slack: how far below the roof's highest part a sparse
//   scan's second highest point may lie: a roof is sampled from above at the
//   scan's spacing, and cambered by a few centimetres over a sample spacing;
//   a thin rack or antenna the model's dense cloud holds may fall between
//   samples.
// - bottom_gap_spacings: without terrain, the lowest features lie on a
//   side's lowest sampled row: above the vehicle's lowest visible part by up
//   to a sample spacing up the side, s / cos(e) for views at elevation e
//   (1.4 s at 45 degrees), where a scan of spacing s returns about
//   (1.6 / s)^2 points per m^2 of the top with the sides, so
//   2.3 / sqrt(density), and the model's box bottom is its cloud's lowest
//   point, itself that far above the ground. Steeper views show less of the
//   sides: their lower part is often unseen and the class flag withheld
//   without terrain.
// - min_height_density: without terrain the height is measured only where
//   that allowance is finer than the step between classes; below about 50
//   points per m^2 it is coarser than the step from sedans to vans, and a
//   van's pose sunk under a low saloon passed. A sparse scan then confirms
//   a class only with its terrain.
bool height_measured(const ScanShape& scan, const ClassesParams& p) {
  return scan.on_terrain || scan.density >= p.min_height_density;
}

float span(float lo, float hi) { return hi > lo ? hi - lo : 0.0f; }

// The envelope of the models `member` takes.
template <typename Member>
ClassEnvelope envelope_of_models(const Database& db, Member&& member) {
  ClassEnvelope e;
  for (uint32_t m = 0; m < db.model_count(); ++m) {
    const blob::ModelRecord& r = db.model(m);
    if (!member(r)) continue;
    const float dx = span(r.bbox_min[0], r.bbox_max[0]), dy = span(r.bbox_min[1], r.bbox_max[1]);
    const float length = dx > dy ? dx : dy, width = dx > dy ? dy : dx;
    const float height = span(r.bbox_min[2], r.bbox_max[2]);
    if (e.members == 0u) {
      e.length_max = length, e.width_max = width, e.height_min = e.height_max = height;
    } else {
      e.length_max = length > e.length_max ? length : e.length_max;
      e.width_max = width > e.width_max ? width : e.width_max;
      e.height_min = height < e.height_min ? height : e.height_min;
      e.height_max = height > e.height_max ? height : e.height_max;
    }
    ++e.members;
  }
  return e;
}

}  // namespace

ClassEnvelope class_envelope(const Database& db, uint32_t vehicle_class) {
  return envelope_of_models(
      db, [vehicle_class](const blob::ModelRecord& r) { return r.vehicle_class == vehicle_class; });
}

ClassEnvelope group_envelope(const Database& db, uint32_t group) {
  return envelope_of_models(
      db, [group](const blob::ModelRecord& r) { return static_cast<uint32_t>(model_group(r)) == group; });
}

ScanShape measure_scan(const QueryFeatures& query, const blob::ModelRecord& leader, const RigidPose& pose,
                       float top_above_terrain, float terrain_sigma, float sigma_surface, float density) {
  ScanShape s;
  s.density = density;
  s.spacing = density > 0.0f ? 1.0f / std::sqrt(density) : kFar;
  s.on_terrain = top_above_terrain >= 0.0f;
  s.noise = s.on_terrain ? terrain_sigma : sigma_surface;
  if (query.count < 2u) return s;
  // The two outermost features each side along the model's axes, and along
  // the query's vertical (z up, georeferenced): a pose that fits a lower
  // vehicle may tilt, and the model's z then takes in some of its length.
  float lo[2][4], hi[2][4];
  for (int k = 0; k < 2; ++k)
    for (int a = 0; a < 4; ++a) lo[k][a] = kFar, hi[k][a] = -kFar;
  const Eigen::Matrix3f to_model = pose.rotation.transpose();
  for (uint32_t f = 0; f < query.count; ++f) {
    const Eigen::Map<const Eigen::Vector3f> p(query.positions + 3u * f);
    const Eigen::Vector3f m = to_model * (p - pose.translation);
    const float x[4] = {m[0], m[1], m[2], p[2]};
    for (int a = 0; a < 4; ++a) {
      if (x[a] < lo[1][a]) lo[1][a] = x[a] < lo[0][a] ? lo[0][a] : x[a];
      if (x[a] < lo[0][a]) lo[0][a] = x[a];
      if (x[a] > hi[1][a]) hi[1][a] = x[a] > hi[0][a] ? hi[0][a] : x[a];
      if (x[a] > hi[0][a]) hi[0][a] = x[a];
    }
  }
  const float sx = span(lo[1][0], hi[1][0]), sy = span(lo[1][1], hi[1][1]);
  s.length = sx > sy ? sx : sy;
  s.width = sx > sy ? sy : sx;
  if (s.on_terrain) {
    s.height = top_above_terrain;
  } else {
    // The scan's vertical span, lifted by how far its lowest features stop
    // above the leader's bottom face: the top above that bottom.
    s.bottom_gap = lo[1][2] - leader.bbox_min[2];
    s.height = span(lo[1][3], hi[1][3]) + (s.bottom_gap > 0.0f ? s.bottom_gap : 0.0f);
  }
  return s;
}

bool within_envelope(const ScanShape& scan, const ClassEnvelope& env, float end_tolerance,
                     const ClassesParams& p) {
  if (env.members == 0u) return false;
  if (scan.length > env.length_max + 2.0f * end_tolerance) return false;  // both ends
  if (scan.width > env.width_max + 2.0f * end_tolerance) return false;
  if (!height_measured(scan, p)) return false;
  if (!scan.on_terrain && scan.bottom_gap > p.bottom_gap_spacings * scan.spacing) return false;
  if (scan.height > env.height_max + p.top_noise_sigmas * scan.noise + p.model_bottom_gap) return false;
  return scan.height >= env.height_min - p.top_sampling_slack;
}

}  // namespace spinhash
