// spinhash.SceneRecognizer: a SceneSession over a Database, the one scene
// path of `spinhash scene` (pipeline/tile_stream.hpp); recognize(tile)
// answers every object of an airborne tile as the command prints them, and
// push(chunk) ... flush() the same for a tile handed over in chunks of any
// order (iter_cloud's), in bounded memory. Releases the GIL like Recognizer.
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
#include "spinhash/scene_fields.h"

namespace py = pybind11;

namespace spinhash::python {
namespace {

std::string type_name(py::handle value) {
  return std::string(py::str(py::type::handle_of(value).attr("__name__")));
}

// A Python value as a scene setting's type: TypeError for another type,
// ValueError for an int beyond the field's type.
uint32_t setting_value(uint32_t*, const std::string& key, py::handle value) {
  if (PyBool_Check(value.ptr()) || !PyLong_Check(value.ptr()))
    throw py::type_error(key + " must be an int, got " + type_name(value));
  const long long v = PyLong_AsLongLong(value.ptr());
  if (PyErr_Occurred() || v < 0 || v > 0xFFFFFFFFll) {
    PyErr_Clear();
    throw py::value_error(key + " is out of range: " + std::string(py::repr(value)));
  }
  return static_cast<uint32_t>(v);
}
uint64_t setting_value(uint64_t*, const std::string& key, py::handle value) {
  if (PyBool_Check(value.ptr()) || !PyLong_Check(value.ptr()))
    throw py::type_error(key + " must be an int, got " + type_name(value));
  const unsigned long long v = PyLong_AsUnsignedLongLong(value.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    throw py::value_error(key + " is out of range: " + std::string(py::repr(value)));
  }
  return static_cast<uint64_t>(v);
}
float setting_value(float*, const std::string& key, py::handle value) {
  if (PyBool_Check(value.ptr()) || !(PyLong_Check(value.ptr()) || PyFloat_Check(value.ptr())))
    throw py::type_error(key + " must be a number, got " + type_name(value));
  return py::cast<float>(value);
}

// A scene setting, checked by the core's own rule on an otherwise default config.
template <typename T>
void set_checked(SceneConfig* c, T SceneConfig::*member, const std::string& key, py::handle value) {
  const T v = setting_value(static_cast<T*>(nullptr), key, value);
  SceneConfig probe;
  probe.*member = v;
  const bool sized = key == "max_tile_points" && v == T{0};  // from each tile's density, as the command's
  if (!sized && !scene_config_valid(probe))
    throw py::value_error(key + " is out of range: " + std::string(py::repr(value)));
  c->*member = v;
}

// Takes `key` when it names a field of SPINHASH_SCENE_CONFIG_FIELDS; false
// for the recognizer's settings.
bool set_scene_field(SceneConfig* c, const std::string& key, py::handle value) {
#define SPINHASH_PY_SCENE_FIELD(kind, name, lo, hi, flag, help) \
  if (key == #name) {                                           \
    set_checked(c, &SceneConfig::name, key, value);             \
    return true;                                                \
  }
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_PY_SCENE_FIELD)
#undef SPINHASH_PY_SCENE_FIELD
  return false;
}

// One value per kind of SPINHASH_SCENE_STATS_FIELDS.
py::object stat_U32(uint32_t v) { return py::int_(v); }
py::object stat_U64(uint64_t v) { return py::int_(v); }
py::object stat_SIZE(size_t v) { return py::int_(v); }
py::object stat_KINDS(const uint32_t (&by_kind)[kObjectKinds]) {
  py::dict kinds;
  for (uint32_t k = 0; k < kObjectKinds; ++k) kinds[object_kind_name(ObjectKind(k))] = by_kind[k];
  return std::move(kinds);
}

py::dict scene_stats(const SceneStats& st) {
  py::dict d;
#define SPINHASH_PY_SCENE_STAT(kind, name, key) d[key] = stat_##kind(st.name);
  SPINHASH_SCENE_STATS_FIELDS(SPINHASH_PY_SCENE_STAT)
#undef SPINHASH_PY_SCENE_STAT
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
    return answer([&] { return session_.recognize(xyz); });
  }

  void push(py::handle points) {
    const std::vector<double> xyz = points_from_array(points);
    std::string failure;
    {
      py::gil_scoped_release unlocked;
      std::lock_guard<std::mutex> one_at_a_time(busy_);
      try {
        session_.push(xyz.data(), xyz.size() / 3);
      } catch (const std::runtime_error& e) {
        failure = e.what();
      }
    }
    if (!failure.empty()) throw py::value_error("scene: " + failure);
  }

  py::list flush() {
    return answer([&] { return session_.flush(); });
  }

  const std::string& last_status() const { return last_status_; }
  const SceneConfig& config() const { return config_; }
  const py::dict& last_stats() const { return last_stats_; }

 private:
  // Runs a tile without the GIL; its objects as SceneObject. A refused tile
  // is a ValueError; a tile with more than max_objects objects a warning.
  template <class Call>
  py::list answer(Call call) {
    SceneResult r;
    std::vector<SceneObjectCopy> objects;
    std::string failure;
    {
      py::gil_scoped_release unlocked;
      std::lock_guard<std::mutex> one_at_a_time(busy_);
      try {
        r = call();
      } catch (const std::runtime_error& e) {
        failure = e.what();
      }
      for (uint32_t k = 0; k < r.object_count; ++k) {
        const SceneObject& o = r.objects[k];
        SceneObjectCopy c{o, std::vector<RankedModel>(o.ranking, o.ranking + o.ranking_count)};
        c.object.ranking = nullptr;
        objects.push_back(std::move(c));
      }
    }
    if (!failure.empty()) throw py::value_error("scene: " + failure);
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
  scene.max_tile_points = 0;  // sized from each tile's density, as `spinhash scene`
  RecognizerConfig base;
  base.ground.ground_clearance =
      0.0f;  // the scene's terrain classifier removes the ground (as `spinhash scene`)
  py::kwargs recognizer_kwargs;
  for (auto item : kwargs) {
    const std::string key = py::cast<std::string>(item.first);
    if (!set_scene_field(&scene, key, item.second)) recognizer_kwargs[item.first] = item.second;
  }
  scene.recognizer = recognizer_config(base, config, recognizer_kwargs);
  return scene;
}

py::dict scene_stats_dict(const SceneStats& st) { return scene_stats(st); }

void bind_scene(py::module_& m) {
  py::class_<PySceneRecognizer> cls(m, "SceneRecognizer",
                                    "Finds and recognises every vehicle in an airborne lidar tile (z up), as "
                                    "`spinhash scene` does.");
  cls.def(py::init(&make_scene), py::arg("db"), py::arg("config") = py::none(),
          "SceneRecognizer(db, config=None, top_n=5, max_tile_points=0, max_objects=256, **settings): "
          "any SceneConfig field by name (docs/api.md), the others as spinhash.Config's (ground_clearance "
          "defaults to 0: the terrain is removed; max_tile_points 0: sized from each tile's density)")
      .def("recognize", &PySceneRecognizer::recognize, py::arg("points"),
           "Every object of an (N, 3) float64 tile, in any order: a list of SceneObject, as `spinhash scene` "
           "answers the tile. ValueError when the tile is refused (window_overflow: a window held more than "
           "max_tile_points points, ...); a RuntimeWarning when only the first max_objects were answered.")
      .def("push", &PySceneRecognizer::push, py::arg("points"),
           "Adds an (N, 3) float64 chunk of the tile, in any order (iter_cloud's chunks as they come): "
           "ordered along track in bounded memory; flush() answers the tile.")
      .def("flush", &PySceneRecognizer::flush,
           "Every object of the chunks pushed since the last flush, as recognize() answers them whole.")
      .def_property_readonly("last_status", &PySceneRecognizer::last_status,
                             "status word of the last tile ('ok', 'too_many_objects', 'empty_cloud', ...)")
      .def_property_readonly("last_stats", &PySceneRecognizer::last_stats,
                             "stage statistics of the last tile")
      .def_property_readonly(
          "config", [](const PySceneRecognizer& s) { return s.config().recognizer; },
          "a copy of the settings each vehicle candidate is recognised with");
  // Every scene setting, read-only (spinhash/scene_fields.h).
#define SPINHASH_PY_SCENE_PROPERTY(kind, name, lo, hi, flag, help) \
  cls.def_property_readonly(                                       \
      #name, [](const PySceneRecognizer& s) { return s.config().name; }, help);
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_PY_SCENE_PROPERTY)
#undef SPINHASH_PY_SCENE_PROPERTY
}

}  // namespace spinhash::python
