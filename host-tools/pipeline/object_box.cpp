#include "pipeline/object_box.hpp"

#include "pipeline/recognition_session.hpp"

namespace spinhash::pipeline {

host::PictureBox object_box(const Database& db, const SceneObject& o, double metres_per_unit) {
  host::PictureBox b;
  b.center[0] = o.center[0], b.center[1] = o.center[1];
  b.length = o.extent[0] / metres_per_unit, b.width = o.extent[1] / metres_per_unit,
  b.heading_deg = o.heading_deg;
  if (o.kind == ObjectKind::kVehicleCandidate && o.ranking_count > 0) {
    b.label = model_name(db, o.ranking[0].model) + (o.confident ? "" : " ?");
    b.style = o.confident ? host::BoxStyle::kConfident : host::BoxStyle::kUnsure;
  } else {
    b.label = object_kind_name(o.kind);
    b.style = o.kind == ObjectKind::kVehicleCandidate || o.kind == ObjectKind::kUnknown
                  ? host::BoxStyle::kUnsure
                  : host::BoxStyle::kNotVehicle;
  }
  return b;
}

}  // namespace spinhash::pipeline
