// The C++ survey for spinhash.survey (python/spinhash/survey.py): prepare
// (catalogue, plan, resume) and finish (the outputs) on the client, and one
// tile's task on a worker, with the very code `spinhash survey` runs, so the
// results are the same byte for byte.
#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cloud/crs_resolve.hpp"
#include "cloud/point_source.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/spill_folder.hpp"
#include "py_database.hpp"
#include "spinhash/limits.hpp"
#include "survey/survey_runner.hpp"
#include "survey/tile_run.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

// As `spinhash survey`'s --top and --max-objects (limits.hpp, scene_fields.h).
SceneConfig survey_scene(uint32_t top_n, uint32_t max_objects) {
  if (top_n < 1 || top_n > kMaxSceneTopN)
    throw py::value_error("top_n must be in [1, " + std::to_string(kMaxSceneTopN) + "]");
  if (max_objects < 1 || max_objects > kMaxSceneObjects)
    throw py::value_error("max_objects must be in [1, " + std::to_string(kMaxSceneObjects) + "]");
  SceneConfig c = survey::default_survey_scene();
  c.top_n = top_n, c.max_objects = max_objects;
  return c;
}

class PySurvey {
 public:
  explicit PySurvey(survey::PreparedSurvey s) : s_(std::move(s)), start_(std::chrono::steady_clock::now()) {}

  // (name, path, task text) of every tile not done yet, in path order.
  std::vector<std::tuple<std::string, std::string, std::string>> pending() const {
    std::vector<std::tuple<std::string, std::string, std::string>> v;
    for (size_t i = 0; i < s_.tasks.size(); ++i)
      if (!s_.done[i])
        v.emplace_back(s_.tasks[i].tile.name, s_.tasks[i].tile.path, survey::task_text(s_.tasks[i]));
    return v;
  }

  void store(const std::string& text) const {
    survey::TileResult r;
    std::string error;
    if (!survey::parse_result_text(text, &r, &error)) throw py::value_error("survey result: " + error);
    if (!survey::store_result(s_.options.out_dir, r, &error)) throw std::runtime_error(error);
  }

  int finish(const std::vector<std::tuple<std::string, std::string, std::string>>& failed, unsigned workers) {
    s_.options.jobs = workers;  // survey.json records the workers that ran the tasks
    std::vector<survey::Refusal> f;
    for (const auto& t : failed) f.push_back(survey::refusal(std::get<0>(t), std::get<1>(t), std::get<2>(t)));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string error;
    const int code = survey::finish_survey(s_, f, wall, &error);
    if (code == pipeline::kExitError) throw std::runtime_error(error);
    return code;
  }

  size_t tiles() const { return s_.catalogue.tiles.size(); }
  size_t tiles_planned() const { return s_.tasks.size(); }
  // The tiles a previous run finished with the same inputs (resume), kept.
  std::vector<std::string> kept() const {
    std::vector<std::string> v;
    for (size_t i = 0; i < s_.tasks.size(); ++i)
      if (s_.done[i]) v.push_back(s_.tasks[i].tile.name);
    return v;
  }
  std::string crs() const { return s_.catalogue.crs.proj_definition(); }
  std::vector<std::tuple<std::string, std::string, std::string>> refused() const {
    std::vector<std::tuple<std::string, std::string, std::string>> v;
    for (const survey::Refusal& r : s_.refused) v.emplace_back(r.tile, r.path, r.reason);
    return v;
  }

 private:
  survey::PreparedSurvey s_;
  std::chrono::steady_clock::time_point start_;
};

std::unique_ptr<PySurvey> prepare(const std::string& db_path, const std::vector<std::string>& tiles,
                                  const std::string& out_dir, double buffer, bool resume, uint32_t top_n,
                                  uint32_t max_objects, const std::string& work_crs,
                                  const std::vector<int>& drop_classes) {
  if (!(buffer >= survey::kMinBuffer && buffer <= survey::kMaxBuffer))
    throw py::value_error("buffer must be in [0, 1000] m");
  survey::SurveyOptions o;
  o.db_path = db_path, o.out_dir = out_dir, o.buffer = buffer, o.resume = resume;
  o.scene = survey_scene(top_n, max_objects);
  if (!work_crs.empty()) {
    std::string error;
    if (!host::crs_from_user(work_crs, &o.work.crs, &error)) throw py::value_error("work_crs: " + error);
    if (o.work.crs.units.geographic)
      throw py::value_error("work_crs: " + work_crs +
                            " is in degrees: name a projected CRS (metres or feet)");
    o.work.named = true;
  }
  std::string class_error;
  if (!host::add_drop_classes(drop_classes, &o.filter, &class_error))
    throw py::value_error("drop_classes: " + class_error);
  pipeline::report_stale_spill_folders("survey");  // what killed workers on this machine left
  survey::PreparedSurvey s;
  std::string error;
  if (!survey::prepare_survey(o, tiles, &s, &error)) throw py::value_error("survey: " + error);
  return std::make_unique<PySurvey>(std::move(s));
}

std::string run_task(const std::shared_ptr<PyDatabase>& db, const std::string& task_text, uint32_t top_n,
                     uint32_t max_objects, size_t order_memory) {
  if (!db) throw py::type_error("survey_run_task needs a spinhash.Database");
  if (order_memory < pipeline::kMinOrderMemoryPoints || order_memory > pipeline::kMaxOrderMemoryPoints)
    throw py::value_error("order_memory must be " + std::to_string(pipeline::kMinOrderMemoryPoints) + " to " +
                          std::to_string(pipeline::kMaxOrderMemoryPoints) + " points");
  const SceneConfig scene = survey_scene(top_n, max_objects);
  static std::once_flag swept;  // a worker's first task: what killed workers of this machine left
  std::call_once(swept, [] { pipeline::remove_stale_spill_folders(); });
  survey::SurveyTask task;
  std::string error;
  if (!survey::parse_task_text(task_text, &task, &error)) throw py::value_error("survey task: " + error);
  py::gil_scoped_release unlocked;
  try {
    return survey::result_text(survey::run_task(db->file.db, task, scene, order_memory));
  } catch (const host::CloudError& e) {
    py::gil_scoped_acquire locked;
    PyErr_SetString(PyExc_OSError, e.what());
    throw py::error_already_set();
  }
}

}  // namespace

void bind_survey(py::module_& m) {
  py::class_<PySurvey>(m, "_Survey", "a prepared survey (spinhash.survey drives it)")
      .def("pending", &PySurvey::pending, "(name, path, task) of each tile left to run, in path order")
      .def("store", &PySurvey::store, py::arg("result"), "stores a tile's result atomically in OUT/tiles/")
      .def("finish", &PySurvey::finish, py::arg("failed"), py::arg("workers") = 0u,
           "writes the outputs from the stored results; the exit status of `spinhash survey`")
      .def_property_readonly("tiles", &PySurvey::tiles)
      .def_property_readonly("tiles_planned", &PySurvey::tiles_planned,
                             "tiles with a task (readable headers)")
      .def_property_readonly("kept", &PySurvey::kept, "tiles a previous run finished, kept (resume)")
      .def_property_readonly("crs", &PySurvey::crs, "the tiles' PROJ definition ('' when unknown)")
      .def_property_readonly("refused", &PySurvey::refused,
                             "(name, path, reason) of tiles whose header failed");
  m.def("_survey_prepare", &prepare, py::arg("db_path"), py::arg("tiles"), py::arg("out_dir"),
        py::arg("buffer") = survey::kDefaultBuffer, py::arg("resume") = false, py::arg("top_n") = 5u,
        py::arg("max_objects") = 256u, py::arg("work_crs") = "",
        py::arg("drop_classes") = std::vector<int>{});
  m.attr("_ORDER_MEMORY_POINTS") = pipeline::kOrderMemoryPoints;  // --order-memory's default
  m.def("_survey_run_task", &run_task, py::arg("db"), py::arg("task"), py::arg("top_n") = 5u,
        py::arg("max_objects") = 256u, py::arg("order_memory") = pipeline::kOrderMemoryPoints,
        "one survey task (its tile with the neighbours' buffer): the tile's result as text; order_memory: "
        "points of the tile held in memory while it is ordered (as --order-memory). OSError when the tile or "
        "a neighbour cannot be read.");
}

}  // namespace spinhash::python
