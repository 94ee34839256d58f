// scene: matching one tile's detections to its truth.
#include <cmath>
#include <cstdio>

#include "pipeline/recognition_session.hpp"
#include "scene_data.hpp"

namespace spinhash::experiment {
namespace {

using host::SceneObjectKind;

double xy_distance(const double a[3], const Eigen::Vector3d& b) {
  return std::hypot(a[0] - b.x(), a[1] - b.y());
}

// Objects that stand for a detected vehicle: vehicle-sized ones, recognised or not.
bool vehicle_sized(const SceneObject& o) {
  return o.kind == ObjectKind::kVehicleCandidate || o.kind == ObjectKind::kUnknown;
}

// Whether xy lies within the truth object's footprint grown by kMatchDistance.
bool covers(const host::SceneTruth& s, const double xy[3]) {
  const double h = s.heading_deg * 3.141592653589793 / 180.0;
  const double dx = xy[0] - s.center.x(), dy = xy[1] - s.center.y();
  const double along = dx * std::cos(h) + dy * std::sin(h), across = -dx * std::sin(h) + dy * std::cos(h);
  return std::abs(along) <= 0.5 * s.extent.x() + kMatchDistance &&
         std::abs(across) <= 0.5 * s.extent.y() + kMatchDistance;
}

std::string first_model(const Database& db, const SceneObject& o) {
  return o.ranking_count > 0 ? pipeline::model_name(db, o.ranking[0].model) : std::string();
}

}  // namespace

std::string SceneCondition::label() const {
  char buf[96];
  std::snprintf(buf, sizeof buf, "slope %g, spacing %g, noise %g", slope_deg, spacing, noise);
  return buf;
}

void score_tile(const host::SceneScan& scan, const SceneResult& result, const Database& db,
                uint32_t condition, uint32_t tile, double ms, SceneRun* run) {
  SceneTileRecord t;
  t.condition = condition, t.tile = tile, t.ms = ms;
  t.points = static_cast<uint32_t>(scan.size());
  t.objects = result.object_count;
  std::vector<bool> used(result.object_count, false);  // matched to a database vehicle
  // Each vehicle (known or unknown) takes the nearest unused vehicle-sized object within reach.
  for (const host::SceneTruth& v : scan.objects) {
    if (v.kind != SceneObjectKind::kVehicle && v.kind != SceneObjectKind::kUnknownVehicle) continue;
    SceneVehicleRecord r;
    r.condition = condition, r.tile = tile, r.kind = v.kind, r.model = v.model;
    r.flags = v.flags, r.points = v.points;
    int best = -1;
    double best_d = kMatchDistance;
    for (uint32_t k = 0; k < result.object_count; ++k) {
      const double d = xy_distance(result.objects[k].center, v.center);
      if (!used[k] && vehicle_sized(result.objects[k]) && d <= best_d) best = static_cast<int>(k), best_d = d;
    }
    if (best < 0) {
      double near = kNearestReach;
      for (uint32_t k = 0; k < result.object_count; ++k) {
        const double d = xy_distance(result.objects[k].center, v.center);
        if (!used[k] && vehicle_sized(result.objects[k]) && d < near)
          near = d, r.nearest_m = d, r.nearest_answer = first_model(db, result.objects[k]);
      }
    }
    if (best >= 0) {
      const SceneObject& o = result.objects[best];
      r.found = true, r.distance = best_d, r.answer = first_model(db, o), r.confident = o.confident;
      r.score = o.ranking_count > 0 ? o.ranking[0].score : 0.0;
      r.score_second = o.ranking_count > 1 ? o.ranking[1].score : 0.0;
      r.features = o.stats.extract.features;
      r.ground_gap = o.ground_gap;
      if (v.kind == SceneObjectKind::kVehicle)
        used[best] = true;  // an unknown vehicle's answer stays a candidate alarm
    }
    if (v.kind == SceneObjectKind::kVehicle) {
      ++t.vehicles;
      t.found += r.found ? 1u : 0u;
      const bool right = r.found && r.answer == v.model;
      t.top1 += right ? 1u : 0u;
      t.confident_right += right && r.confident ? 1u : 0u;
      t.confident_wrong += r.found && !right && r.confident ? 1u : 0u;
    }
    run->vehicles.push_back(r);
  }
  // Every other confident answer is a false alarm: say what it was on.
  for (uint32_t k = 0; k < result.object_count; ++k) {
    const SceneObject& o = result.objects[k];
    if (used[k] || !o.confident) continue;
    SceneFalseAlarm a;
    a.condition = condition, a.tile = tile, a.answer = first_model(db, o);
    a.score = o.ranking_count > 0 ? o.ranking[0].score : 0.0;
    for (int i = 0; i < 3; ++i) a.extent[i] = o.extent[i];
    a.on = "nothing";
    for (const host::SceneTruth& s : scan.objects) {
      if (covers(s, o.center)) a.on = host::scene_object_kind_name(s.kind);
    }
    ++t.false_alarms;
    run->alarms.push_back(a);
  }
  run->tile_records.push_back(t);
}

}  // namespace spinhash::experiment
