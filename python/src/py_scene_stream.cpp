// spinhash.SceneStream: the core's SceneStream for users who read points
// with their own reader: push(points) returns the objects that the push
// completed, flush() the rest; the same windows and answers as the core.
// Points behind the declared lag are dropped by the core's contract: the
// push warns (RuntimeWarning, last_status "points_late") and names the
// ordering helper (spinhash.AlongTrackOrder, py_scene_order.cpp).
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
#include "spinhash/scene_fields.h"
#include "spinhash/scene_stream.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

// One keyword per kind of SPINHASH_STREAM_CONFIG_FIELDS (the core checks the
// whole config). A BOOL is set by the setting it names (origin_given: origin).
bool take_F32(float* f, py::handle v) {
  *f = py::cast<float>(v);
  return true;
}
bool take_U32(uint32_t* f, py::handle v) {
  *f = py::cast<uint32_t>(v);
  return true;
}
bool take_BOOL(bool*, py::handle) { return false; }
bool take_VEC3D(double (*f)[3], py::handle v) {
  const auto o = py::cast<std::vector<double>>(v);
  if (o.size() != 3) throw py::value_error("origin must be 3 numbers (x, y, z)");
  for (int a = 0; a < 3; ++a) (*f)[a] = o[static_cast<size_t>(a)];
  return true;
}

// The stream's own settings (the frame, swath, order and buffer), by keyword.
bool take_stream_setting(StreamConfig* c, const std::string& key, py::handle v) {
#define SPINHASH_PY_STREAM_FIELD(kind, name, lo, hi, flag, help) \
  if (key == #name) return take_##kind(&c->name, v);
  SPINHASH_STREAM_CONFIG_FIELDS(SPINHASH_PY_STREAM_FIELD)
#undef SPINHASH_PY_STREAM_FIELD
  return false;
}

// One value per kind of SPINHASH_STREAM_STATS_FIELDS.
py::object stat_SCENE(const SceneStats& st) { return scene_stats_dict(st); }
py::object stat_U64(uint64_t v) { return py::int_(v); }
py::object stat_F64(double v) { return py::float_(v); }

py::dict stream_stats(const StreamStats& st) {
  py::dict d;
#define SPINHASH_PY_STREAM_STAT(kind, name, key) d[key] = stat_##kind(st.name);
  SPINHASH_STREAM_STATS_FIELDS(SPINHASH_PY_STREAM_STAT)
#undef SPINHASH_PY_STREAM_STAT
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
  // SceneObject. kStreamFlushed is a ValueError; late points and a lost
  // window are warnings.
  template <class Call>
  py::list run(Call call) {
    Status s;
    std::vector<SceneObjectCopy> done;
    uint64_t late = 0;
    {
      py::gil_scoped_release unlocked;
      std::lock_guard<std::mutex> one_at_a_time(busy_);
      const uint64_t late_before = stream_.stats().points_late;
      s = call();
      late = stream_.stats().points_late - late_before;
      done.swap(pending_);
    }
    last_status_ = pipeline::status_word(s);
    if (s == Status::kStreamFlushed || s == Status::kInvalidArgument || s == Status::kNotOpen)
      throw py::value_error("SceneStream: " + last_status_ + " (" + status_name(s) + ")");
    if (late > 0) {
      const std::string message =
          "SceneStream: points_late: " + std::to_string(late) + " points (" +
          std::to_string(stream_.stats().points_late) +
          " in all) came more than max_lag behind the furthest pushed and were dropped; push in along-track "
          "order, or order the chunks first with spinhash.AlongTrackOrder";
      if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1) < 0) throw py::error_already_set();
    }
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
    if (take_stream_setting(&c, py::cast<std::string>(item.first), item.second)) {
      if (py::cast<std::string>(item.first) == "origin") c.origin_given = true;
    } else {
      rest[item.first] = item.second;
    }
  c.scene = scene_config_from(config, rest);
  if (c.scene.max_tile_points == 0)
    c.scene.max_tile_points = SceneConfig{}.max_tile_points;  // a fixed window
  if (!stream_config_valid(c))
    throw py::value_error("SceneStream: invalid settings (see stream_config_valid)");
  return std::make_unique<PySceneStream>(db, c);
}

}  // namespace

void bind_scene_stream(py::module_& m) {
  py::class_<PySceneStream>(
      m, "SceneStream",
      "A flight line of any length in fixed memory: push points in scan order (along-track "
      "lag at most max_lag), get each object once, as soon as its window is complete. Points further "
      "behind are dropped with a RuntimeWarning (last_status 'points_late'); order chunks of any order "
      "with spinhash.AlongTrackOrder first.")
      .def(py::init(&make_stream), py::arg("db"), py::arg("config") = py::none(),
           "SceneStream(db, config=None, heading_deg=90, swath_min=-128, swath_max=128, own_min=-128, "
           "own_max=128, max_lag=16, max_jump=500, jump_confirm_points=16, max_z_offset=3000, "
           "max_buffered_points=8388608, "
           "origin=None, "
           "top_n=5, max_tile_points=2097152, max_objects=256, **settings)")
      .def("push", &PySceneStream::push, py::arg("points"),
           "Pushes an (N, 3) float64 chunk; returns the SceneObjects of the windows it completed.")
      .def("flush", &PySceneStream::flush, "Ends the line: the SceneObjects of the windows still pending.")
      .def("reset", &PySceneStream::reset, "Starts a new line with the same settings.")
      .def_property_readonly("stats", &PySceneStream::stats, "what the stream did, lost points counted")
      .def_property_readonly("last_status", &PySceneStream::last_status, "status word of the last call");
  bind_along_track_order(m);
}

}  // namespace spinhash::python
