#include "py_result.hpp"

#include <cmath>
#include <string>

#include "bindings.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/status_word.hpp"
#include "points.hpp"
#include "spinhash/config_fields.h"

namespace py = pybind11;

namespace spinhash::python {
namespace {

py::object stat_value(bool v) { return py::bool_(v); }
py::object stat_value(uint32_t v) { return py::int_(v); }
py::object stat_value(uint64_t v) { return py::int_(v); }
py::object stat_value(float v) { return py::float_(static_cast<double>(v)); }

// Every entry of SPINHASH_STATS_FIELDS, under its JSON key.
py::dict stats_dict(const RecognitionStats& st) {
  py::dict d;
#define SPINHASH_PY_STAT(kind, name, member, json) d[json] = stat_value(st.member);
  SPINHASH_STATS_FIELDS(SPINHASH_PY_STAT)
#undef SPINHASH_PY_STAT
  return d;
}

py::list ranking_list(const Database& db, const std::vector<RankedModel>& ranking) {
  py::list out;
  for (const RankedModel& m : ranking)
    out.append(py::make_tuple(pipeline::model_name(db, m.model), static_cast<double>(m.score)));
  return out;
}

py::list class_list(const Database& db, const RankedClass* classes, uint32_t count) {
  py::list out;
  for (uint32_t i = 0; i < count; ++i)
    out.append(py::make_tuple(vehicle_class_name(classes[i].vehicle_class),
                              static_cast<double>(classes[i].score),
                              pipeline::model_name(db, classes[i].model)));
  return out;
}

py::object first_class(const RankedClass* classes, uint32_t count) {
  return count > 0 ? py::object(py::str(vehicle_class_name(classes[0].vehicle_class))) : py::none();
}

py::list group_list(const Database& db, const RankedGroup* groups, uint32_t count) {
  py::list out;
  for (uint32_t i = 0; i < count; ++i)
    out.append(py::make_tuple(vehicle_group_name(groups[i].group), static_cast<double>(groups[i].score),
                              pipeline::model_name(db, groups[i].model)));
  return out;
}

py::object first_group(const RankedGroup* groups, uint32_t count) {
  return count > 0 ? py::object(py::str(vehicle_group_name(groups[0].group))) : py::none();
}

// Per calibrated level its flag and evidence (None when a prerequisite
// failed), under the level's name.
py::dict level_dict(const LevelAnswer* levels) {
  py::dict d;
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
    const LevelAnswer a = levels != nullptr ? levels[l] : LevelAnswer{};
    py::dict one;
    one["confident"] = py::bool_(a.confident);
    one["evidence"] = std::isfinite(a.evidence) ? py::object(py::float_(static_cast<double>(a.evidence)))
                                                : py::object(py::none());
    d[answer_level_name(l + 1u)] = one;
  }
  return d;
}

template <typename Out>
void set_levels(const Database& db, const RankedGroup* groups, uint32_t count, const LevelAnswer* levels,
                AnswerLevel level, Out* out) {
  out->group = first_group(groups, count);
  out->group_ranking = group_list(db, groups, count);
  out->levels = level_dict(levels);
  out->level = answer_level_name(static_cast<uint32_t>(level));
}

py::object best_pose(const std::vector<RankedModel>& ranking) {
  if (ranking.empty() || !ranking[0].has_pose) return py::none();
  return pose_matrix(ranking[0].pose);
}

// The answer levels' attributes, alike on Result and SceneObject.
template <typename T>
void def_levels(py::class_<T>& c) {
  c.def_readonly("group", &T::group,
                 "the first group's name (the CLI's \"group\"), e.g. 'light'; None without a ranking")
      .def_readonly("group_ranking", &T::group_ranking,
                    "[(group name, score, best model's name), ...], best first")
      .def_readonly("levels", &T::levels,
                    "{level name: {'confident': bool, 'evidence': float or None}} for 'vehicle', 'group', "
                    "'class' and 'model' (the CLI's \"levels\")")
      .def_readonly("level", &T::level,
                    "the most specific confident level whose coarser levels are confident and consistent: "
                    "'model', 'class', 'group', 'vehicle' or 'none'");
}

}  // namespace

ResultCopy copy_result(const Result& r, double time_ms) {
  ResultCopy c;
  c.result = r;
  c.result.ranking = nullptr;
  if (r.ranking != nullptr) c.ranking.assign(r.ranking, r.ranking + r.ranking_count);
  c.result.class_ranking = nullptr;
  if (r.status == Status::kOk && r.class_ranking != nullptr)
    c.classes.assign(r.class_ranking, r.class_ranking + r.class_ranking_count);
  c.result.group_ranking = nullptr;
  if (r.status == Status::kOk && r.group_ranking != nullptr)
    c.groups.assign(r.group_ranking, r.group_ranking + r.group_ranking_count);
  c.time_ms = time_ms;
  return c;
}

PyResult make_result(const Database& db, const ResultCopy& r) {
  PyResult out;
  out.status = pipeline::status_word(r.result.status);
  out.error = r.result.status == Status::kOk ? py::object(py::none()) : py::str(status_name(r.result.status));
  out.ranking = ranking_list(db, r.ranking);
  out.pose = best_pose(r.ranking);
  out.confident = r.result.confident;
  out.group_size = r.result.status == Status::kOk ? r.result.group_size : 0u;
  const uint32_t classes = static_cast<uint32_t>(r.classes.size());
  out.vehicle_class = first_class(r.classes.data(), classes);
  out.class_confident = r.result.status == Status::kOk && r.result.class_confident;
  out.class_ranking = class_list(db, r.classes.data(), classes);
  const bool ok = r.result.status == Status::kOk;
  set_levels(db, r.groups.data(), static_cast<uint32_t>(r.groups.size()), ok ? r.result.levels : nullptr,
             ok ? r.result.level : AnswerLevel::kNone, &out);
  out.stats = stats_dict(r.result.stats);
  out.time_ms = r.time_ms;
  return out;
}

PySceneObject make_scene_object(const Database& db, const SceneObjectCopy& c) {
  const SceneObject& o = c.object;
  PySceneObject out;
  out.kind = object_kind_name(o.kind);
  out.status = pipeline::status_word(o.status);
  const bool ranked = !c.ranking.empty();
  out.model = ranked ? py::object(py::str(pipeline::model_name(db, c.ranking[0].model))) : py::none();
  out.score = ranked ? py::object(py::float_(static_cast<double>(c.ranking[0].score))) : py::none();
  out.ranking = ranking_list(db, c.ranking);
  out.pose = best_pose(c.ranking);
  out.confident = o.confident;
  out.group_size = o.group_size;
  out.vehicle_class = first_class(o.classes, o.class_count);
  out.class_confident = o.class_confident;
  out.class_ranking = class_list(db, o.classes, o.class_count);
  set_levels(db, o.groups, o.group_count, o.levels, o.level, &out);
  out.ground_gap =
      std::isfinite(o.ground_gap) ? py::object(py::float_(static_cast<double>(o.ground_gap))) : py::none();
  out.points = o.points;
  out.center = py::make_tuple(o.center[0], o.center[1], o.center[2]);
  out.extent = py::make_tuple(static_cast<double>(o.extent[0]), static_cast<double>(o.extent[1]),
                              static_cast<double>(o.extent[2]));
  out.heading_deg = static_cast<double>(o.heading_deg);
  return out;
}

void bind_result(py::module_& m) {
  py::class_<PyResult> result(m, "Result", "One recognition: the fields of the CLI's JSON line.");
  result
      .def_readonly("status", &PyResult::status,
                    "'ok', 'empty_cloud', 'not_enough_features', ... (as the CLI)")
      .def_readonly("error", &PyResult::error, "why, when status is not 'ok'; else None")
      .def_readonly("ranking", &PyResult::ranking, "[(model name, score), ...], best first")
      .def_readonly("pose", &PyResult::pose,
                    "4x4 float64, model frame -> query frame, of the best model; None without one")
      .def_readonly("confident", &PyResult::confident,
                    "the model level's flag: the best model is the scanned one")
      .def_readonly("group_size", &PyResult::group_size,
                    "leading models the scan does not tell apart (within min_margin); 1: the first "
                    "stands alone")
      .def_readonly("vehicle_class", &PyResult::vehicle_class,
                    "the first class's name (the CLI's \"class\"), e.g. 'pickup'; None without a ranking")
      .def_readonly("class_confident", &PyResult::class_confident,
                    "the class level's flag: the first class is the vehicle's")
      .def_readonly("class_ranking", &PyResult::class_ranking,
                    "[(class name, score, best model's name), ...], best first")
      .def_readonly("stats", &PyResult::stats, "the CLI's \"stats\" object as a dict")
      .def_readonly("time_ms", &PyResult::time_ms, "wall time of the recognition, ms")
      .def_property_readonly(
          "model",
          [](const PyResult& r) -> py::object {
            if (r.ranking.empty()) return py::none();
            return py::tuple(r.ranking[0])[size_t{0}];  // a bare 0 would be a null const char* key
          },
          "the best model's name, or None")
      .def("__repr__", [](const PyResult& r) {
        std::string best = r.ranking.empty() ? "None" : std::string(py::repr(r.ranking[0]));
        return "spinhash.Result(status=" + std::string(py::repr(r.status)) + ", best=" + best +
               ", confident=" + (r.confident ? "True" : "False") +
               ", vehicle_class=" + std::string(py::repr(r.vehicle_class)) +
               ", class_confident=" + (r.class_confident ? "True" : "False") + ")";
      });
  def_levels(result);
  py::class_<PySceneObject> object(m, "SceneObject",
                                   "One object of a tile: the fields of a line of `spinhash scene`.");
  object
      .def_readonly("kind", &PySceneObject::kind,
                    "'vehicle', 'too small', 'too large', 'not vehicle-shaped', 'unknown'")
      .def_readonly("status", &PySceneObject::status, "status of its recognition ('ok' when not recognised)")
      .def_readonly("model", &PySceneObject::model, "best model's name (vehicles), else None")
      .def_readonly("score", &PySceneObject::score, "best model's score, else None")
      .def_readonly("ranking", &PySceneObject::ranking, "[(model name, score), ...], best first")
      .def_readonly("pose", &PySceneObject::pose, "4x4 float64 of the best model, or None")
      .def_readonly("confident", &PySceneObject::confident,
                    "a confident recognition that fits the object's size")
      .def_readonly("group_size", &PySceneObject::group_size,
                    "leading models its recognition does not tell apart (within min_margin)")
      .def_readonly("vehicle_class", &PySceneObject::vehicle_class, "the first class's name, or None")
      .def_readonly("class_confident", &PySceneObject::class_confident,
                    "a confident class whose leader fits the object's size")
      .def_readonly("class_ranking", &PySceneObject::class_ranking,
                    "[(class name, score, best model's name), ...], best first")
      .def_readonly("ground_gap", &PySceneObject::ground_gap,
                    "best model's box bottom above the terrain under its pose, m, or None")
      .def_readonly("points", &PySceneObject::points, "points in the object")
      .def_readonly("center", &PySceneObject::center, "(x, y, z): footprint centre, z mid-height")
      .def_readonly("extent", &PySceneObject::extent, "(length, width, height above terrain), m")
      .def_readonly("heading_deg", &PySceneObject::heading_deg,
                    "direction of the length axis, degrees from +x")
      .def("__repr__", [](const PySceneObject& o) {
        return "spinhash.SceneObject(kind=" + std::string(py::repr(o.kind)) +
               ", model=" + std::string(py::repr(o.model)) +
               ", confident=" + (o.confident ? "True" : "False") + ", points=" + std::to_string(o.points) +
               ")";
      });
  def_levels(object);
}

}  // namespace spinhash::python
