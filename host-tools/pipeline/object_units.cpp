#include "pipeline/object_units.hpp"

#include "cloud/metric_source.hpp"

namespace spinhash::pipeline {
namespace {

// ranking's models with their pose translations in the file's units.
const RankedModel* ranking_in_file_units(const RankedModel* r, uint32_t n, const host::AxisUnits& units,
                                         std::vector<RankedModel>* out) {
  out->assign(r, r + n);
  for (RankedModel& m : *out) host::scale_to_file_units(units, m.pose.translation);
  return out->data();
}

}  // namespace

SceneObject in_file_units(const SceneObject& o, const host::AxisUnits& units,
                          std::vector<RankedModel>* ranking) {
  SceneObject f = o;
  if (units.metric()) return f;
  host::scale_to_file_units(units, f.center);
  f.ranking = ranking_in_file_units(o.ranking, o.ranking_count, units, ranking);
  return f;
}

Result in_file_units(const Result& r, const host::AxisUnits& units, std::vector<RankedModel>* ranking) {
  Result f = r;
  if (units.metric()) return f;
  f.ranking = ranking_in_file_units(r.ranking, r.ranking_count, units, ranking);
  return f;
}

}  // namespace spinhash::pipeline
