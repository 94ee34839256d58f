// spinhash.Recognizer: a RecognitionSession (its own workspace) over a
// Database. recognize() releases the GIL, so Recognizers in different threads
// run in parallel; one Recognizer serves one call at a time.
#include <pybind11/stl.h>

#include <memory>
#include <mutex>

#include "bindings.hpp"
#include "pipeline/recognition_session.hpp"
#include "points.hpp"
#include "py_config.hpp"
#include "py_database.hpp"
#include "py_result.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

class PyRecognizer {
 public:
  PyRecognizer(DatabasePtr db, const RecognizerConfig& cfg) : db_(std::move(db)) {
    std::string error;
    if (!session_.init(&db_->file.db, cfg, &error)) throw py::value_error(error);
  }

  PyResult recognize(py::handle points) {
    const std::vector<double> xyz = points_from_array(points);  // copied while the GIL is held
    ResultCopy answer;
    {
      py::gil_scoped_release unlocked;
      std::lock_guard<std::mutex> one_at_a_time(busy_);  // the workspace serves one call
      answer = copy_result(session_.recognize(xyz), session_.last_ms());
    }
    return make_result(db_->file.db, answer);
  }

  const RecognizerConfig& config() const { return session_.config(); }
  DatabasePtr database() const { return db_; }

 private:
  DatabasePtr db_;  // kept alive: the session reads it
  std::mutex busy_;
  pipeline::RecognitionSession session_;
};

std::unique_ptr<PyRecognizer> make_recognizer(const std::shared_ptr<PyDatabase>& db, const py::object& config,
                                              const py::kwargs& kwargs) {
  if (!db) throw py::type_error("Recognizer needs a spinhash.Database");
  return std::make_unique<PyRecognizer>(db, recognizer_config(RecognizerConfig{}, config, kwargs));
}

}  // namespace

void bind_recognizer(py::module_& m) {
  py::class_<PyRecognizer>(m, "Recognizer",
                           "Recognizes (N, 3) float64 point clouds against a Database. Each Recognizer owns "
                           "its workspace; recognize() releases the GIL, so Recognizers in separate threads "
                           "run in parallel.")
      .def(py::init(&make_recognizer), py::arg("db"), py::arg("config") = py::none(),
           "Recognizer(db, config=None, **settings): settings as spinhash.Config's, over config's")
      .def("recognize", &PyRecognizer::recognize, py::arg("points"),
           "Recognizes an (N, 3) float64 array (any strides; NaN rows are dropped and counted): a Result")
      .def_property_readonly(
          "config", [](const PyRecognizer& r) { return r.config(); }, "a copy of the settings in use")
      .def_property_readonly("db", &PyRecognizer::database, "the Database")
      .def_property_readonly(
          "workspace_bytes", [](const PyRecognizer& r) { return required_workspace_bytes(r.config()); },
          "bytes of the workspace the settings need (what firmware would reserve)");
}

}  // namespace spinhash::python
