// spinhash.SceneRecognizer: a SceneSession (its own workspace) over a
// Database; recognize(tile) answers every object of an airborne tile, as
// `spinhash scene` prints them. Releases the GIL like Recognizer.
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <string>

#include "bindings.hpp"
#include "pipeline/scene_session.hpp"
#include "pipeline/status_word.hpp"
#include "points.hpp"
#include "py_config.hpp"
#include "py_database.hpp"
#include "py_result.hpp"
#include "py_scene.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

// The scene's own settings (the CLI's scene options); nullptr for the recognizer's.
uint32_t* scene_field(SceneConfig* c, const std::string& key) {
  if (key == "top_n") return &c->top_n;
  if (key == "max_tile_points") return &c->max_tile_points;
  if (key == "max_objects") return &c->max_objects;
  return nullptr;
}

// A scene setting, checked by the core's own rule on an otherwise default config.
void set_scene_field(SceneConfig* c, const std::string& key, py::handle value) {
  if (PyBool_Check(value.ptr()) || !PyLong_Check(value.ptr()))
    throw py::type_error(key + " must be an int, got " +
                         std::string(py::str(py::type::handle_of(value).attr("__name__"))));
  const long long v = PyLong_AsLongLong(value.ptr());
  SceneConfig probe;
  *scene_field(&probe, key) = static_cast<uint32_t>(v);
  if (PyErr_Occurred() || v < 1 || v > 0xFFFFFFFFll || !scene_config_valid(probe)) {
    PyErr_Clear();
    throw py::value_error(key + " is out of range: " + std::string(py::repr(value)));
  }
  *scene_field(c, key) = static_cast<uint32_t>(v);
}

py::dict scene_stats(const SceneStats& st) {
  py::dict d, kinds;
  d["points"] = st.points_in;
  d["points_nonfinite"] = st.points_nonfinite;
  d["points_ground"] = st.points_ground;
  d["points_in_objects"] = st.points_in_objects;
  d["points_fragments"] = st.points_fragments;
  d["terrain_cells"] = st.terrain_cells;
  d["terrain_windows"] = st.terrain_windows;
  d["segment_cells"] = st.segment_cells;
  d["components"] = st.components;
  d["objects_dropped"] = st.objects_dropped;
  for (uint32_t k = 0; k < kObjectKinds; ++k) kinds[object_kind_name(ObjectKind(k))] = st.objects_by_kind[k];
  d["objects_by_kind"] = kinds;
  d["recognition_hypotheses"] = st.recognition_hypotheses;
  d["recognition_candidates"] = st.recognition_candidates;
  d["workspace_used"] = st.workspace_used;
  return d;
}

class PySceneRecognizer {
 public:
  PySceneRecognizer(DatabasePtr db, const SceneConfig& cfg) : db_(std::move(db)), config_(cfg) {
    std::string error;
    if (!session_.init(&db_->file.db, cfg, &error)) throw py::value_error(error);
  }

  py::list recognize(py::handle points) {
    const std::vector<double> xyz = points_from_array(points);
    SceneResult r;
    std::vector<SceneObjectCopy> objects;
    {
      py::gil_scoped_release unlocked;
      std::lock_guard<std::mutex> one_at_a_time(busy_);
      r = session_.recognize(xyz);
      for (uint32_t k = 0; k < r.object_count; ++k) {
        const SceneObject& o = r.objects[k];
        SceneObjectCopy c{o, std::vector<RankedModel>(o.ranking, o.ranking + o.ranking_count)};
        c.object.ranking = nullptr;
        objects.push_back(std::move(c));
      }
    }
    last_status_ = pipeline::status_word(r.status);
    last_stats_ = scene_stats(r.stats);
    // kTooManyObjects still answers the first max_objects; an empty tile has no objects.
    if (r.status != Status::kOk && r.status != Status::kTooManyObjects && r.status != Status::kEmptyCloud)
      throw py::value_error("scene: " + last_status_ + " (" + status_name(r.status) + ")");
    if (r.status == Status::kTooManyObjects &&
        PyErr_WarnEx(PyExc_RuntimeWarning,
                     "scene: too_many_objects: only the first max_objects were answered", 1) < 0)
      throw py::error_already_set();  // warnings turned into errors
    py::list out;
    for (const SceneObjectCopy& c : objects) out.append(make_scene_object(db_->file.db, c));
    return out;
  }

  const std::string& last_status() const { return last_status_; }
  const SceneConfig& config() const { return config_; }
  const py::dict& last_stats() const { return last_stats_; }

 private:
  DatabasePtr db_;
  SceneConfig config_;
  std::mutex busy_;
  pipeline::SceneSession session_;
  std::string last_status_ = "none";
  py::dict last_stats_;
};

std::unique_ptr<PySceneRecognizer> make_scene(const std::shared_ptr<PyDatabase>& db, const py::object& config,
                                              const py::kwargs& kwargs) {
  if (!db) throw py::type_error("SceneRecognizer needs a spinhash.Database");
  return std::make_unique<PySceneRecognizer>(db, scene_config_from(config, kwargs));
}

}  // namespace

SceneConfig scene_config_from(const py::object& config, const py::kwargs& kwargs) {
  SceneConfig scene;
  RecognizerConfig base;
  base.ground_clearance = 0.0f;  // the scene's terrain classifier removes the ground (as `spinhash scene`)
  py::kwargs recognizer_kwargs;
  for (auto item : kwargs) {
    const std::string key = py::cast<std::string>(item.first);
    if (scene_field(&scene, key) != nullptr)
      set_scene_field(&scene, key, item.second);
    else
      recognizer_kwargs[item.first] = item.second;
  }
  scene.recognizer = recognizer_config(base, config, recognizer_kwargs);
  return scene;
}

py::dict scene_stats_dict(const SceneStats& st) { return scene_stats(st); }

void bind_scene(py::module_& m) {
  py::class_<PySceneRecognizer>(m, "SceneRecognizer",
                                "Finds and recognises every vehicle in an airborne lidar tile (z up), as "
                                "`spinhash scene` does.")
      .def(py::init(&make_scene), py::arg("db"), py::arg("config") = py::none(),
           "SceneRecognizer(db, config=None, top_n=5, max_tile_points=2097152, max_objects=256, **settings): "
           "settings as spinhash.Config's (ground_clearance defaults to 0: the terrain is removed)")
      .def("recognize", &PySceneRecognizer::recognize, py::arg("points"),
           "Every object of an (N, 3) float64 tile: a list of SceneObject. ValueError when the tile is "
           "refused (window_overflow: a window held more than max_tile_points points, ...); a RuntimeWarning "
           "when only the first max_objects were answered.")
      .def_property_readonly("last_status", &PySceneRecognizer::last_status,
                             "status word of the last tile ('ok', 'too_many_objects', 'empty_cloud', ...)")
      .def_property_readonly("last_stats", &PySceneRecognizer::last_stats,
                             "stage statistics of the last tile")
      .def_property_readonly(
          "config", [](const PySceneRecognizer& s) { return s.config().recognizer; },
          "a copy of the settings each vehicle candidate is recognised with")
      .def_property_readonly("top_n", [](const PySceneRecognizer& s) { return s.config().top_n; })
      .def_property_readonly("max_tile_points",
                             [](const PySceneRecognizer& s) { return s.config().max_tile_points; })
      .def_property_readonly("max_objects",
                             [](const PySceneRecognizer& s) { return s.config().max_objects; });
}

}  // namespace spinhash::python
