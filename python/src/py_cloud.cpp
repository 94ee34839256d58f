// spinhash.read_cloud: LAS, LAZ, PLY or x y z text into an (N, 3) float64
// array, through the reader the CLI uses; spinhash.read_cloud_header: a
// file's header (count, bounds, format, CRS) without its points;
// spinhash.iter_cloud: the points in chunks of bounded size (a LAZ chunk is
// decoded at a time), so memory does not grow with the file.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud/crs_units.hpp"
#include "cloud/point_source.hpp"
#include "points.hpp"
#include "py_errors.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

void require_exists(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) raise_file_not_found(path.string() + ": no such file");
}

py::array_t<double> read_cloud(const std::filesystem::path& path) {
  require_exists(path);
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

py::dict crs_dict(const host::Crs& crs) {
  py::dict d;
  d["name"] = crs.describe();
  d["epsg"] = crs.horizontal_epsg == 0 ? py::object(py::none()) : py::int_(crs.horizontal_epsg);
  d["vertical_epsg"] = crs.vertical_epsg == 0 ? py::object(py::none()) : py::int_(crs.vertical_epsg);
  d["wkt"] = crs.wkt.empty() ? py::object(py::none()) : py::str(crs.wkt);
  d["source"] = crs.source.empty() ? py::object(py::none()) : py::str(crs.source);
  d["warnings"] = crs.warnings;
  // Metres per unit (cloud/crs_units.hpp): the recognizers take metres.
  const host::AxisUnits u = host::axis_units(crs);
  d["metres_per_unit"] =
      u.geographic ? py::object(py::none()) : py::object(py::make_tuple(u.horizontal, u.vertical));
  d["unit_notes"] = u.messages();
  return d;
}

py::dict header_dict(const host::CloudHeader& h) {
  py::dict d;
  d["format"] = h.format;
  d["point_count"] = h.count_known ? py::object(py::int_(h.point_count)) : py::object(py::none());
  d["bounds"] = h.bounds_known ? py::object(py::make_tuple(py::make_tuple(h.min[0], h.min[1], h.min[2]),
                                                           py::make_tuple(h.max[0], h.max[1], h.max[2])))
                               : py::object(py::none());
  const bool las = h.format == "las" || h.format == "laz";
  d["las_point_format"] = las ? py::object(py::int_(h.las_point_format)) : py::object(py::none());
  d["las_version"] =
      las ? py::object(py::make_tuple(h.las_version[0], h.las_version[1])) : py::object(py::none());
  d["crs"] = crs_dict(h.crs);
  return d;
}

std::unique_ptr<host::PointSource> open_source(const std::filesystem::path& path) {
  require_exists(path);
  try {
    py::gil_scoped_release unlocked;
    return host::open_point_source(path.string());
  } catch (const host::CloudError& e) {
    throw py::value_error(e.what());
  }
}

py::dict read_cloud_header(const std::filesystem::path& path) {
  return header_dict(open_source(path)->header());
}

// Iterates over (n, 3) float64 arrays of at most chunk_points rows.
class ChunkIterator {
 public:
  ChunkIterator(std::unique_ptr<host::PointSource> source, size_t chunk_points)
      : source_(std::move(source)), chunk_points_(chunk_points) {}
  py::dict header() const { return header_dict(source_->header()); }
  py::array_t<double> next() {
    std::vector<double> xyz(3 * chunk_points_);
    size_t n = 0;
    try {
      py::gil_scoped_release unlocked;
      n = source_->read(xyz.data(), chunk_points_);
    } catch (const host::CloudError& e) {
      throw py::value_error(e.what());
    }
    if (n == 0) throw py::stop_iteration();
    xyz.resize(3 * n);
    return array_from_points(xyz);
  }

 private:
  std::unique_ptr<host::PointSource> source_;
  size_t chunk_points_;
};

std::unique_ptr<ChunkIterator> iter_cloud(const std::filesystem::path& path, size_t chunk_points) {
  if (chunk_points == 0) throw py::value_error("chunk_points must be at least 1");
  return std::make_unique<ChunkIterator>(open_source(path), chunk_points);
}

}  // namespace

void bind_cloud(py::module_& m) {
  m.def("read_cloud", &read_cloud, py::arg("path"),
        "Reads a point cloud file (LAS 1.0-1.4, LAZ and COPC, PLY, or x y z text, as the spinhash command) "
        "into "
        "an (N, 3) float64 array. FileNotFoundError, or ValueError naming what is wrong with the file.");
  m.def("read_cloud_header", &read_cloud_header, py::arg("path"),
        "A cloud file's header without its points (LAS/LAZ: format, point_count, bounds, las_point_format, "
        "las_version, crs {name, epsg, vertical_epsg, wkt, source, warnings, metres_per_unit (x y, z; None "
        "for degrees), unit_notes}). PLY and text are read to "
        "count.");
  py::class_<ChunkIterator>(m, "CloudChunks", "The points of a cloud file in (n, 3) float64 chunks.")
      .def("__iter__", [](ChunkIterator& self) -> ChunkIterator& { return self; })
      .def("__next__", &ChunkIterator::next)
      .def_property_readonly("header", &ChunkIterator::header);
  m.def("iter_cloud", &iter_cloud, py::arg("path"), py::arg("chunk_points") = host::kDefaultChunkPoints,
        "Iterates over a cloud file's points in (n, 3) float64 arrays of at most chunk_points rows; LAS and "
        "LAZ "
        "are read a chunk at a time (memory does not grow with the file). ValueError on a malformed file.");
}

}  // namespace spinhash::python
