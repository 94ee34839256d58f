// spinhash.read_cloud: LAS, LAZ, PLY or x y z text into an (N, 3) float64
// array, through the reading door the CLI uses (its own coordinates, or
// metres / a CRS to work in through cloud/metric_source.hpp); spinhash.read_cloud_header: a
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
#include "cloud/crs_resolve.hpp"
#include "cloud/crs_units.hpp"
#include "cloud/metric_source.hpp"
#include "cloud/point_source.hpp"
#include "points.hpp"
#include "py_errors.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

void require_exists(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) raise_file_not_found(path.string() + ": no such file");
}

// The CRS to work in, as the CLI's --work-crs; none: the file's own.
host::WorkCrs work_crs(const py::object& text) {
  host::WorkCrs w;
  if (text.is_none()) return w;
  std::string error;
  if (!host::crs_from_user(py::cast<std::string>(text), &w.crs, &error)) throw py::value_error(error);
  if (w.crs.units.geographic)
    throw py::value_error(py::cast<std::string>(text) +
                          " is in degrees: name a projected CRS (metres or feet)");
  w.named = true;
  return w;
}

// The classes to leave out besides noise, as the CLI's --drop-class.
host::PointFilter point_filter(const std::vector<int>& classes) {
  host::PointFilter f;
  std::string error;
  if (!host::add_drop_classes(classes, &f, &error)) throw py::value_error("drop_classes: " + error);
  return f;
}

// The file through the reading door: its own coordinates, or (metres, or a
// CRS to work in) through cloud/metric_source.hpp.
std::unique_ptr<host::PointSource> open_source(const std::filesystem::path& path, const py::object& work,
                                               bool metres, const std::vector<int>& drop_classes) {
  require_exists(path);
  const host::WorkCrs w = work_crs(work);
  const host::PointFilter filter = point_filter(drop_classes);
  try {
    py::gil_scoped_release unlocked;
    if (!metres && !w.named) return host::open_point_source(path.string(), filter);
    return host::open_metric_source(path.string(), w, filter);
  } catch (const host::CloudError& e) {
    throw py::value_error(e.what());
  }
}

// Metres back to the work CRS's units when the caller asked for its coordinates.
void in_units(host::PointSource& source, bool metres, std::vector<double>* xyz) {
  const auto* m = dynamic_cast<const host::MetricSource*>(&source);
  if (metres || m == nullptr) return;
  const host::AxisUnits& u = m->to_metres().units();
  for (size_t i = 0; i + 3 <= xyz->size(); i += 3) host::scale_to_file_units(u, xyz->data() + i);
}

py::array_t<double> read_cloud(const std::filesystem::path& path, const py::object& work, bool metres,
                               const std::vector<int>& drop_classes) {
  std::unique_ptr<host::PointSource> source = open_source(path, work, metres, drop_classes);
  std::vector<double> xyz;
  try {
    py::gil_scoped_release unlocked;
    xyz = host::read_all_points(*source);
    in_units(*source, metres, &xyz);
  } catch (const host::CloudError& e) {
    throw py::value_error(e.what());
  }
  return array_from_points(xyz);
}

py::dict crs_dict(const host::Crs& crs) {
  py::dict d;
  d["name"] = crs.describe();
  d["epsg"] = crs.id_epsg == 0 ? py::object(py::none()) : py::int_(crs.id_epsg);
  d["vertical_epsg"] = crs.id_vertical_epsg == 0 ? py::object(py::none()) : py::int_(crs.id_vertical_epsg);
  d["wkt"] = crs.wkt.empty() ? py::object(py::none()) : py::str(crs.wkt);
  d["definition"] = crs.known() ? py::object(py::str(crs.proj_definition())) : py::object(py::none());
  d["source"] = crs.source.empty() ? py::object(py::none()) : py::str(crs.source);
  d["warnings"] = crs.warnings;
  // Metres per unit (cloud/crs_units.hpp): the recognizers take metres.
  const host::AxisUnits u = host::axis_units(crs);
  d["units"] = py::make_tuple(u.horizontal_name, u.vertical_name);
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

py::dict read_cloud_header(const std::filesystem::path& path) {
  return header_dict(open_source(path, py::none(), false, {})->header());
}

// Iterates over (n, 3) float64 arrays of at most chunk_points rows.
class ChunkIterator {
 public:
  ChunkIterator(std::unique_ptr<host::PointSource> source, size_t chunk_points, bool metres)
      : source_(std::move(source)), chunk_points_(chunk_points), metres_(metres) {}
  py::dict header() const { return header_dict(source_->header()); }
  uint64_t points_noise() const { return source_->points_noise(); }
  py::array_t<double> next() {
    std::vector<double> xyz(3 * chunk_points_);
    size_t n = 0;
    try {
      py::gil_scoped_release unlocked;
      n = source_->read(xyz.data(), chunk_points_);
      xyz.resize(3 * n);
      in_units(*source_, metres_, &xyz);
    } catch (const host::CloudError& e) {
      throw py::value_error(e.what());
    }
    if (n == 0) throw py::stop_iteration();
    return array_from_points(xyz);
  }

 private:
  std::unique_ptr<host::PointSource> source_;
  size_t chunk_points_;
  bool metres_;
};

std::unique_ptr<ChunkIterator> iter_cloud(const std::filesystem::path& path, size_t chunk_points,
                                          const py::object& work, bool metres,
                                          const std::vector<int>& drop_classes) {
  if (chunk_points == 0) throw py::value_error("chunk_points must be at least 1");
  return std::make_unique<ChunkIterator>(open_source(path, work, metres, drop_classes), chunk_points, metres);
}

}  // namespace

void bind_cloud(py::module_& m) {
  m.def(
      "read_cloud", &read_cloud, py::arg("path"), py::kw_only(), py::arg("work_crs") = py::none(),
      py::arg("metres") = false, py::arg("drop_classes") = std::vector<int>{},
      "Reads a point cloud file (LAS 1.0-1.4, LAZ and COPC, PLY, or x y z text, as the spinhash command) "
      "into an (N, 3) float64 array, in the file's own coordinates, without the points a LAS/LAZ file marks "
      "as noise (ASPRS classes 7 and 18) or withheld, or of a class in drop_classes (LAS classes 0-255, "
      "as the CLI's --drop-class: a producer's own artefact class); with work_crs (\"EPSG:32610\", a WKT "
      "or a PROJ string: a projected CRS), reprojected into it when the file is in another CRS; with "
      "metres=True, in metres (what the recognizers take: feet scaled; degrees refused unless work_crs "
      "is given). FileNotFoundError, or ValueError naming what is wrong with the file.");
  m.def("read_cloud_header", &read_cloud_header, py::arg("path"),
        "A cloud file's header without its points (LAS/LAZ: format, point_count, bounds, las_point_format, "
        "las_version, crs {name, epsg, vertical_epsg, wkt, definition (what PROJ reads), source, warnings, "
        "units "
        "(x y, z names), metres_per_unit (x y, z; None "
        "for degrees), unit_notes}). PLY and text are read to "
        "count.");
  py::class_<ChunkIterator>(m, "CloudChunks", "The points of a cloud file in (n, 3) float64 chunks.")
      .def("__iter__", [](ChunkIterator& self) -> ChunkIterator& { return self; })
      .def("__next__", &ChunkIterator::next)
      .def_property_readonly("header", &ChunkIterator::header)
      .def_property_readonly("points_noise", &ChunkIterator::points_noise,
                             "points read so far that a LAS/LAZ file marks as noise (ASPRS classes 7 and 18) "
                             "or withheld, or of a class in drop_classes: left out of the chunks");
  m.def(
      "iter_cloud", &iter_cloud, py::arg("path"), py::arg("chunk_points") = host::kDefaultChunkPoints,
      py::kw_only(), py::arg("work_crs") = py::none(), py::arg("metres") = false,
      py::arg("drop_classes") = std::vector<int>{},
      "Iterates over a cloud file's points in (n, 3) float64 arrays of at most chunk_points rows; LAS and "
      "LAZ "
      "are read a chunk at a time (memory does not grow with the file); work_crs, metres and drop_classes as "
      "read_cloud. "
      "ValueError on a malformed file.");
}

}  // namespace spinhash::python
