#include "survey/tile_run.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "pipeline/json_line.hpp"
#include "pipeline/object_box.hpp"
#include "pipeline/object_json.hpp"
#include "pipeline/object_units.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/status_word.hpp"
#include "pipeline/tile_stream.hpp"
#include "pipeline/version.hpp"
#include "survey/buffered_source.hpp"
#include "survey/footprint.hpp"

namespace spinhash::survey {
namespace {

using pipeline::json_string;

// The survey's members: the scene's, then the CRS, the native footprint and
// the version. The JSON line, the GeoJSON properties and the GeoPackage's
// columns all come from this one list.
// o in the survey CRS's units (pipeline/object_units.hpp).
std::vector<pipeline::JsonMember> survey_members(const SurveyTask& task, uint32_t k, const Database& db,
                                                 const SceneObject& o) {
  std::vector<pipeline::JsonMember> m = pipeline::object_members(task.tile.name, k, db, o);
  m.push_back({"crs", json_string(task.crs_name)});
  m.push_back({"footprint", "[" + ring_json(footprint(o, task.units.horizontal), kNativeDigits) + "]"});
  m.push_back({"version", json_string(pipeline::version())});
  return m;
}

std::string feature_json(const std::vector<pipeline::JsonMember>& members, const SceneObject& o,
                         double metres_per_unit, const ToWgs84* to_wgs84) {
  const Ring native = footprint(o, metres_per_unit);
  const std::string ring =
      to_wgs84 ? ring_json(to_wgs84->transform(native), kLonLatDigits) : ring_json(native, kNativeDigits);
  return "{\"type\":\"Feature\",\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[" + ring +
         "]},\"properties\":" + pipeline::members_json(members) + "}";
}

// A detection with every member set and every real number fractional, so
// that its members' JSON shows each one's type.
SceneObject typed_example(RankedModel* ranked) {
  ranked->score = 0.5f;
  ranked->has_pose = true;
  SceneObject o{};
  o.kind = ObjectKind::kVehicleCandidate;
  o.ranking = ranked;
  o.ranking_count = 1;
  o.class_count = 1;
  o.classes[0].score = 0.5f;
  o.group_count = 1;
  o.groups[0].score = 0.5f;
  o.ground_gap = 0.25f;
  o.heading_deg = 12.5f;
  o.points = 7;
  o.group_size = 1;
  for (int a = 0; a < 3; ++a) o.center[a] = 0.5, o.extent[a] = 1.5f;
  return o;
}

ColumnType type_of(const std::string& raw) {
  if (raw.empty() || raw[0] == '"') return ColumnType::kString;
  if (raw[0] == '[' || raw[0] == '{') return ColumnType::kJson;
  if (raw == "true" || raw == "false") return ColumnType::kBoolean;
  return raw.find_first_of(".eE") == std::string::npos ? ColumnType::kInteger : ColumnType::kReal;
}

void count(TileResult& r, const Database& db, const SceneObject& o) {
  ++r.kinds[object_kind_name(o.kind)];
  if (o.kind != ObjectKind::kVehicleCandidate || o.ranking_count == 0) return;
  ModelCount& m = r.models[pipeline::model_name(db, o.ranking[0].model)];
  ++m.candidates;
  m.confident += o.confident ? 1u : 0u;
}

}  // namespace

std::vector<OwnedArea> owner_areas(const SurveyTask& task, uint32_t* self) {
  std::vector<const TaskTile*> tiles{&task.tile};
  for (const TaskTile& n : task.neighbours) tiles.push_back(&n);
  std::stable_sort(tiles.begin(), tiles.end(),
                   [](const TaskTile* a, const TaskTile* b) { return a->path < b->path; });
  std::vector<OwnedArea> areas;
  for (const TaskTile* t : tiles) {
    if (t == &task.tile) *self = static_cast<uint32_t>(areas.size());
    OwnedArea a;
    std::copy(t->core.min, t->core.min + 2, a.min);
    std::copy(t->core.max, t->core.max + 2, a.max);
    areas.push_back(a);
  }
  return areas;
}

TileResult run_task(const Database& db, const SurveyTask& task, const SceneConfig& scene,
                    size_t order_memory_points) {
  const auto t0 = std::chrono::steady_clock::now();
  TileResult r;
  r.index = task.index, r.name = task.tile.name, r.path = task.tile.path, r.key = task.key;
  RankedModel ranked{};
  for (const pipeline::JsonMember& m : survey_members(task, 0, db, typed_example(&ranked)))
    r.columns.push_back({m.key, type_of(m.value)});
  std::unique_ptr<ToWgs84> to_wgs84 = task.crs.empty() ? nullptr : std::make_unique<ToWgs84>(task.crs);
  BufferedSource source(task);
  pipeline::TileStreamOptions options;
  options.scene = scene;
  if (task.segment_cell > 0.0f) {  // the survey's, the same for every tile
    options.scene.segment_cell = task.segment_cell;
    options.segment_cell_from_density = false;
  }
  options.order_memory_points = order_memory_points;
  options.owners = owner_areas(task, &options.self);  // metres, as the door hands the points
  options.owner_tolerance = kGapTolerance;
  const pipeline::ObjectCallback keep = [&](const SceneObject& metres) {  // the tile's own
    std::vector<RankedModel> ranking;
    const SceneObject o = pipeline::in_file_units(metres, task.units, &ranking);
    const auto members = survey_members(task, static_cast<uint32_t>(r.lines.size()), db, o);
    r.lines.push_back(pipeline::members_json(members));
    if (o.kind == ObjectKind::kVehicleCandidate)
      r.features.push_back(feature_json(members, o, task.units.horizontal, to_wgs84.get()));
    count(r, db, o);
    r.boxes.push_back(pipeline::object_box(db, metres));  // the overview is drawn in metres
  };
  const pipeline::TileStreamResult s = pipeline::stream_tile(db, source, options, keep);
  r.status = pipeline::status_word(s.status);
  r.points_tile = source.tile_points(), r.points_buffer = source.buffer_points();
  r.points_noise = source.points_noise();
  r.objects_not_owned += s.objects_not_owned;
  r.objects_in_holes += s.objects_in_holes;
  r.read_ms = s.read_ms, r.stream_ms = s.stream_ms;
  r.total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace spinhash::survey
