// spinhash.read_cloud: LAS, PLY or x y z text into an (N, 3) float64 array,
// through the reader the CLI uses.
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cloud/cloud_reader.hpp"
#include "points.hpp"
#include "py_errors.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

py::array_t<double> read_cloud(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) raise_file_not_found(path.string() + ": no such file");
  std::vector<double> xyz;
  std::string error;
  bool ok;
  {
    py::gil_scoped_release unlocked;
    ok = host::read_cloud(path.string(), &xyz, &error);
  }
  if (!ok) throw py::value_error(error);
  return array_from_points(xyz);
}

}  // namespace

void bind_cloud(py::module_& m) {
  m.def("read_cloud", &read_cloud, py::arg("path"),
        "Reads a point cloud file (LAS 1.0-1.4, PLY, or x y z text, as the spinhash command) into an (N, 3) "
        "float64 array. FileNotFoundError, or ValueError naming what is wrong with the file.");
}

}  // namespace spinhash::python
