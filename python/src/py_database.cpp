#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>

#include "bindings.hpp"
#include "pipeline/recognition_session.hpp"
#include "py_database.hpp"
#include "py_errors.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

DatabasePtr open_file(const std::filesystem::path& path) {
  auto db = std::make_shared<PyDatabase>();
  db->source = path.string();
  if (!std::filesystem::exists(path)) raise_file_not_found(db->source + ": no such file");
  std::string error;
  bool ok;
  {
    py::gil_scoped_release unlocked;  // reading and validating a large blob takes a while
    ok = pipeline::load_database(db->source, &db->file, &error);
  }
  if (!ok) throw py::value_error(error);
  return db;
}

DatabasePtr open_bytes(const py::buffer& bytes) {
  const py::buffer_info view = bytes.request();
  if (view.ndim != 1 || view.itemsize != 1 || view.strides[0] != 1)
    throw py::type_error(
        "Database.from_bytes needs contiguous bytes-like data (bytes, bytearray, memoryview)");
  auto db = std::make_shared<PyDatabase>();
  db->source = "<bytes>";
  // A 64-byte aligned copy, as Database::open requires; the caller's buffer may go away.
  db->file.bytes = host::AlignedBytes::copy_of(static_cast<const uint8_t*>(view.ptr), view.size);
  if (db->file.bytes.empty()) throw py::value_error("Database.from_bytes: empty, not a database");
  const Status s = Database::open(db->file.bytes.data(), db->file.bytes.size(), &db->file.db);
  if (s != Status::kOk) throw py::value_error(std::string("Database.from_bytes: ") + status_name(s));
  return db;
}

py::list model_names(const PyDatabase& d) {
  py::list names;
  for (uint32_t m = 0; m < d.file.db.model_count(); ++m) names.append(pipeline::model_name(d.file.db, m));
  return names;
}

// One dict per model: name, class, group, feature count and bounding-box extent (as `spinhash info` prints).
py::list models(const PyDatabase& d) {
  py::list out;
  for (uint32_t m = 0; m < d.file.db.model_count(); ++m) {
    const blob::ModelRecord& r = d.file.db.model(m);
    py::dict model;
    model["name"] = pipeline::model_name(d.file.db, m);
    model["class"] = vehicle_class_name(r.vehicle_class);
    model["group"] = vehicle_group_name(model_group(r));
    model["features"] = r.feature_count;
    model["extent"] = py::make_tuple(static_cast<double>(r.bbox_max[0] - r.bbox_min[0]),
                                     static_cast<double>(r.bbox_max[1] - r.bbox_min[1]),
                                     static_cast<double>(r.bbox_max[2] - r.bbox_min[2]));
    out.append(model);
  }
  return out;
}

// What `spinhash info` prints above the model table, as a dict.
py::dict info(const PyDatabase& d) {
  const Database& db = d.file.db;
  const blob::Params& p = db.params();
  py::dict i;
  i["format_version"] = db.header().version;
  i["bytes"] = d.file.bytes.size();
  i["fingerprint"] = db.header().config_fingerprint;
  i["models"] = p.model_count;
  i["features"] = p.feature_count;
  i["bins_alpha"] = p.bins_alpha;
  i["bins_beta"] = p.bins_beta;
  i["support_radius"] = p.support_radius;
  i["support_angle_deg"] = p.support_angle_deg;
  i["spin_quant_scale"] = p.spin_quant_scale;
  i["cloud_voxel"] = p.cloud_voxel;
  i["normal_radius"] = p.normal_radius;
  i["basis_spacing"] = p.basis_spacing;
  i["lsh_tables"] = p.lsh_tables;
  i["lsh_bits"] = p.lsh_bits;
  i["lsh_buckets"] = p.lsh_buckets;
  i["lsh_dc"] = p.lsh_dc;
  i["grid_cell"] = p.grid_cell;
  i["grid_offset_count"] = p.grid_offset_count;
  i["field_cell"] = p.field_cell;  // 0: no nearest-feature field
  i["field_reach"] = p.field_reach;
  i["field_slots"] = p.field_slots;
  i["field_entry_count"] = p.field_entry_count;
  return i;
}

}  // namespace

void bind_database(py::module_& m) {
  py::class_<PyDatabase, std::shared_ptr<PyDatabase>>(m, "Database",
                                                      "A spinhash database (.shdb), validated on opening.")
      .def(py::init(&open_file), py::arg("path"),
           "Reads and validates a database file (FileNotFoundError, ValueError naming the problem).")
      .def_static("from_bytes", &open_bytes, py::arg("data"),
                  "Opens a database held in bytes (copied; ValueError when it is not a valid database).")
      .def_property_readonly("names", &model_names, "model names, in database order")
      .def_property_readonly("models", &models,
                             "one dict per model: name, class, features, extent (x, y, z in m)")
      .def_property_readonly("info", &info, "format, size and the parameters the database was built with")
      .def("__len__", [](const PyDatabase& d) { return d.file.db.model_count(); })
      .def("__repr__", [](const PyDatabase& d) {
        return "spinhash.Database('" + d.source + "', " + std::to_string(d.file.db.model_count()) +
               " models)";
      });
}

}  // namespace spinhash::python
