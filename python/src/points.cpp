#include "points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace py = pybind11;

namespace spinhash::python {
namespace {

constexpr py::ssize_t kCoordinates = 3;  // x y z per point
// float32 clouds are widened to double; a coordinate this large is held to
// steps coarser than a centimetre (float32's 24 bits: 2^17 m -> 1/64 m),
// the scale of lidar point spacing and of the poses' translations.
constexpr double kFloat32WarnAbove = 131072.0;

std::string metres_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

template <class T>
std::vector<double> rows_of(const py::array& a) {
  const auto rows = py::reinterpret_borrow<py::array_t<T>>(a).template unchecked<2>();  // honours strides
  std::vector<double> xyz(static_cast<size_t>(rows.shape(0) * kCoordinates));
  for (py::ssize_t i = 0; i < rows.shape(0); ++i)
    for (py::ssize_t k = 0; k < kCoordinates; ++k)
      xyz[static_cast<size_t>(i * kCoordinates + k)] = static_cast<double>(rows(i, k));
  return xyz;
}

// A float32 cloud whose coordinates float32 cannot hold to a centimetre.
void warn_float32_precision(const std::vector<double>& xyz) {
  double largest = 0.0;
  for (double v : xyz)
    if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  if (largest < kFloat32WarnAbove) return;
  const double step = std::nextafter(static_cast<float>(largest), INFINITY) - static_cast<float>(largest);
  const std::string message =
      "float32 points: coordinates up to " + metres_text(largest) + " are held only to steps of " +
      metres_text(step) +
      " (georeferenced coordinates need float64: read them with spinhash.read_cloud, or "
      "subtract an offset before converting to float32)";
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 2) != 0) throw py::error_already_set();
}

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

}  // namespace

std::vector<double> points_from_array(py::handle points) {
  if (!py::isinstance<py::array>(points))
    throw py::type_error("points must be a numpy array of shape (N, 3), dtype float64 or float32; got " +
                         std::string(py::str(py::type::handle_of(points).attr("__name__"))));
  const auto a = py::reinterpret_borrow<py::array>(points);
  const bool f64 = py::array_t<double>::check_(a), f32 = py::array_t<float>::check_(a);
  if (!f64 && !f32)
    throw py::type_error("points must have dtype float64 or float32, got " + std::string(py::str(a.dtype())) +
                         " (use points.astype(numpy.float64))");
  if (a.ndim() != 2 || a.shape(1) != kCoordinates)
    throw py::value_error("points must have shape (N, 3), got " + shape_text(a));
  if (f64) return rows_of<double>(a);
  std::vector<double> xyz = rows_of<float>(a);
  warn_float32_precision(xyz);
  return xyz;
}

py::array_t<double> array_from_points(const std::vector<double>& xyz) {
  const auto n = static_cast<py::ssize_t>(xyz.size() / kCoordinates);
  py::array_t<double> out({n, kCoordinates});
  std::copy(xyz.begin(), xyz.begin() + n * kCoordinates, out.mutable_data());
  return out;
}

py::array_t<double> pose_matrix(const Pose& p) {
  py::array_t<double> m({4, 4});
  auto w = m.mutable_unchecked<2>();
  for (py::ssize_t r = 0; r < 3; ++r) {
    for (py::ssize_t c = 0; c < 3; ++c) w(r, c) = static_cast<double>(p.rotation[3 * r + c]);
    w(r, 3) = p.translation[r];
    w(3, r) = 0.0;
  }
  w(3, 3) = 1.0;
  return m;
}

}  // namespace spinhash::python
