// spinhash.SceneStream: the core's SceneStream for users who read points
// with their own reader: push(points) returns the objects that the push
// completed, flush() the rest; the same windows and answers as the core.
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "blob/aligned_bytes.hpp"
#include "pipeline/status_word.hpp"
#include "points.hpp"
#include "py_database.hpp"
#include "py_result.hpp"
#include "py_scene.hpp"
#include "spinhash/scene_stream.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

// The stream's own settings (the frame, swath, order and buffer), by keyword.
bool take_stream_setting(StreamConfig* c, const std::string& key, py::handle v) {
  if (key == "heading_deg")
    c->heading_deg = py::cast<float>(v);
  else if (key == "swath_min")
    c->swath_min = py::cast<float>(v);
  else if (key == "swath_max")
    c->swath_max = py::cast<float>(v);
  else if (key == "own_min")
    c->own_min = py::cast<float>(v);
  else if (key == "own_max")
    c->own_max = py::cast<float>(v);
  else if (key == "max_lag")
    c->max_lag = py::cast<float>(v);
  else if (key == "max_jump")
    c->max_jump = py::cast<float>(v);
  else if (key == "max_z_offset")
    c->max_z_offset = py::cast<float>(v);
  else if (key == "max_buffered_points")
    c->max_buffered_points = py::cast<uint32_t>(v);
  else if (key == "origin") {
    const auto o = py::cast<std::vector<double>>(v);
    if (o.size() != 3) throw py::value_error("origin must be 3 numbers (x, y, z)");
    c->origin_given = true;
    for (int a = 0; a < 3; ++a) c->origin[a] = o[a];
  } else {
    return false;
  }
  return true;
}

py::dict stream_stats(const StreamStats& st) {
  py::dict d;
  d["scene"] = scene_stats_dict(st.scene);
  d["points_pushed"] = st.points_pushed;
  d["points_outside"] = st.points_outside;
  d["points_late"] = st.points_late;
  d["points_glitch"] = st.points_glitch;
  d["points_overflow"] = st.points_overflow;
  d["points_after_flush"] = st.points_after_flush;
  d["windows"] = st.windows;
  d["windows_overflowed"] = st.windows_overflowed;
  d["points_in_overflowed"] = st.points_in_overflowed;
  d["objects_reported"] = st.objects_reported;
  d["objects_not_owned"] = st.objects_not_owned;
  d["furthest_along"] = st.furthest_along;
  d["done_until"] = st.done_until;
  return d;
}

class PySceneStream {
 public:
  PySceneStream(DatabasePtr db, const StreamConfig& cfg) : db_(std::move(db)) {
    const size_t bytes = required_stream_workspace_bytes(cfg);
    if (bytes == 0) throw py::value_error("SceneStream: invalid settings (see stream_config_valid)");
    workspace_ = host::AlignedBytes(bytes);
    const Status s = stream_.init(&db_->file.db, cfg, workspace_.data(), bytes, collect, &pending_);
    if (s != Status::kOk) throw py::value_error(std::string("SceneStream: ") + status_name(s));
  }

  py::list push(py::handle points) {
    const std::vector<double> xyz = points_from_array(points);
    return run([&] { return stream_.push(xyz.data(), static_cast<uint32_t>(xyz.size() / 3)); });
  }
  py::list flush() {
    return run([&] { return stream_.flush(); });
  }
  void reset() {
    std::lock_guard<std::mutex> one_at_a_time(busy_);
    stream_.reset();
    last_status_ = "none";
  }
  py::dict stats() const { return stream_stats(stream_.stats()); }
  const std::string& last_status() const { return last_status_; }

 private:
  static void collect(void* context, const SceneObject& o, int64_t, uint32_t) {
    SceneObjectCopy c{o, std::vector<RankedModel>(o.ranking, o.ranking + o.ranking_count)};
    c.object.ranking = nullptr;
    static_cast<std::vector<SceneObjectCopy>*>(context)->push_back(std::move(c));
  }

  // Runs a push or flush without the GIL; the objects it completed, as
  // SceneObject. kStreamFlushed is a ValueError; a lost window a warning.
  template <class Call>
  py::list run(Call call) {
    Status s;
    std::vector<SceneObjectCopy> done;
    {
      py::gil_scoped_release unlocked;
      std::lock_guard<std::mutex> one_at_a_time(busy_);
      s = call();
      done.swap(pending_);
    }
    last_status_ = pipeline::status_word(s);
    if (s == Status::kStreamFlushed || s == Status::kInvalidArgument || s == Status::kNotOpen)
      throw py::value_error("SceneStream: " + last_status_ + " (" + status_name(s) + ")");
    if (s == Status::kWindowOverflow &&
        PyErr_WarnEx(PyExc_RuntimeWarning, "SceneStream: window_overflow: points or windows lost (see stats)",
                     1) < 0)
      throw py::error_already_set();
    py::list out;
    for (const SceneObjectCopy& c : done) out.append(make_scene_object(db_->file.db, c));
    return out;
  }

  DatabasePtr db_;
  host::AlignedBytes workspace_;
  SceneStream stream_;
  std::vector<SceneObjectCopy> pending_;
  std::mutex busy_;
  std::string last_status_ = "none";
};

std::unique_ptr<PySceneStream> make_stream(const std::shared_ptr<PyDatabase>& db, const py::object& config,
                                           const py::kwargs& kwargs) {
  if (!db) throw py::type_error("SceneStream needs a spinhash.Database");
  StreamConfig c;
  py::kwargs rest;
  for (auto item : kwargs)
    if (!take_stream_setting(&c, py::cast<std::string>(item.first), item.second))
      rest[item.first] = item.second;
  c.scene = scene_config_from(config, rest);
  if (!stream_config_valid(c))
    throw py::value_error("SceneStream: invalid settings (see stream_config_valid)");
  return std::make_unique<PySceneStream>(db, c);
}

}  // namespace

void bind_scene_stream(py::module_& m) {
  py::class_<PySceneStream>(
      m, "SceneStream",
      "A flight line of any length in fixed memory: push points in scan order (along-track "
      "lag at most max_lag), get each object once, as soon as its window is complete.")
      .def(py::init(&make_stream), py::arg("db"), py::arg("config") = py::none(),
           "SceneStream(db, config=None, heading_deg=90, swath_min=-128, swath_max=128, own_min=-128, "
           "own_max=128, max_lag=16, max_jump=500, max_z_offset=3000, max_buffered_points=8388608, "
           "origin=None, "
           "top_n=5, max_tile_points=2097152, max_objects=256, **settings)")
      .def("push", &PySceneStream::push, py::arg("points"),
           "Pushes an (N, 3) float64 chunk; returns the SceneObjects of the windows it completed.")
      .def("flush", &PySceneStream::flush, "Ends the line: the SceneObjects of the windows still pending.")
      .def("reset", &PySceneStream::reset, "Starts a new line with the same settings.")
      .def_property_readonly("stats", &PySceneStream::stats, "what the stream did, lost points counted")
      .def_property_readonly("last_status", &PySceneStream::last_status, "status word of the last call");
}

}  // namespace spinhash::python
