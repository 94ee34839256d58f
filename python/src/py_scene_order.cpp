// spinhash.AlongTrackOrder: the library's ordering helper for a SceneStream
// (pipeline/tile_stream_order.hpp): chunks of any order pushed in, handed
// back in along-track order in bounded memory (a memory budget, then a
// temporary file), so that iter_cloud's chunks as they come give the
// stream what the whole cloud sorted along track gives it.
#include <pybind11/numpy.h>

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/tile_stream_order.hpp"
#include "points.hpp"
#include "py_scene.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

class PyAlongTrackOrder;

// The points handed back, in (n, 3) float64 chunks.
class OrderedChunks {
 public:
  OrderedChunks(std::shared_ptr<pipeline::AlongTrackOrder> order, size_t chunk_points)
      : order_(std::move(order)), cursor_(*order_, INT64_MIN, INT64_MAX), chunk_points_(chunk_points) {}
  py::array_t<double> next() {
    std::vector<double> xyz(3 * chunk_points_);
    size_t n = 0;
    std::string failure;
    {
      py::gil_scoped_release unlocked;
      try {
        n = cursor_.read(xyz.data(), chunk_points_);
      } catch (const std::runtime_error& e) {
        failure = e.what();
      }
    }
    if (!failure.empty()) throw py::value_error("AlongTrackOrder: " + failure);
    if (n == 0) throw py::stop_iteration();
    xyz.resize(3 * n);
    return array_from_points(xyz);
  }

 private:
  std::shared_ptr<pipeline::AlongTrackOrder> order_;  // kept alive while its points are read
  pipeline::AlongTrackOrder::Cursor cursor_;
  size_t chunk_points_;
};

class PyAlongTrackOrder {
 public:
  PyAlongTrackOrder(double heading_deg, double row_depth, size_t memory_points) {
    if (!(row_depth > 0.0)) throw py::value_error("AlongTrackOrder: row_depth must be > 0 (m)");
    if (memory_points == 0) throw py::value_error("AlongTrackOrder: memory_points must be at least 1");
    order_ = std::make_shared<pipeline::AlongTrackOrder>(heading_deg, row_depth, 0.0, memory_points);
  }
  void push(py::handle points) {
    if (reading_) throw py::value_error("AlongTrackOrder: push after chunks(): make a new order");
    const std::vector<double> xyz = points_from_array(points);
    std::string failure;
    {
      py::gil_scoped_release unlocked;
      try {
        order_->add(xyz.data(), xyz.size() / 3);
      } catch (const std::runtime_error& e) {
        failure = e.what();
      }
    }
    if (!failure.empty()) throw py::value_error("AlongTrackOrder: " + failure);
  }
  std::unique_ptr<OrderedChunks> chunks(size_t chunk_points) {
    if (chunk_points == 0) throw py::value_error("chunk_points must be at least 1");
    reading_ = true;
    return std::make_unique<OrderedChunks>(order_, chunk_points);
  }
  uint64_t points() const { return order_->points(); }
  uint64_t nonfinite() const { return order_->nonfinite(); }

 private:
  std::shared_ptr<pipeline::AlongTrackOrder> order_;
  bool reading_ = false;
};

}  // namespace

void bind_along_track_order(py::module_& m) {
  py::class_<OrderedChunks>(m, "OrderedChunks", "An AlongTrackOrder's points in (n, 3) float64 chunks.")
      .def("__iter__", [](OrderedChunks& self) -> OrderedChunks& { return self; })
      .def("__next__", &OrderedChunks::next);
  py::class_<PyAlongTrackOrder>(
      m, "AlongTrackOrder",
      "Orders points of any order along track in bounded memory, for a SceneStream: push chunks as they "
      "come (iter_cloud's), then push chunks() into the stream. Rows of row_depth m along heading_deg (set "
      "it to the stream's heading, row_depth at most its max_lag); within a row the points keep their order.")
      .def(
          py::init<double, double, size_t>(), py::arg("heading_deg") = 90.0, py::arg("row_depth") = 16.0,
          py::arg("memory_points") = pipeline::kOrderMemoryPoints,
          "AlongTrackOrder(heading_deg=90, row_depth=16, memory_points=4194304): points beyond memory_points "
          "go to a temporary file, removed with the order")
      .def("push", &PyAlongTrackOrder::push, py::arg("points"),
           "Adds an (N, 3) float64 chunk (non-finite points are counted and left out).")
      .def("chunks", &PyAlongTrackOrder::chunks, py::arg("chunk_points") = size_t{1} << 16,
           "The points pushed, in along-track order, as (n, 3) float64 chunks.")
      .def_property_readonly("points", &PyAlongTrackOrder::points, "finite points pushed")
      .def_property_readonly("nonfinite", &PyAlongTrackOrder::nonfinite, "non-finite points left out");
}

}  // namespace spinhash::python
