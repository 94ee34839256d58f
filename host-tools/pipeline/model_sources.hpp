// Model meshes named by the command line, and their virtual scans: the
// paper's model clouds (8 views at 45 degrees elevation, all round), so that
// model and query sampling match.
#pragma once
#include <string>
#include <vector>

#include "db/database_builder.hpp"
#include "mesh/mesh.hpp"

namespace spinhash::pipeline {

struct ModelMesh {
  std::string name;  // file stem
  host::Mesh mesh;
  VehicleClass vehicle_class = VehicleClass::kUnclassified;  // model_classes.hpp
  VehicleGroup vehicle_group = VehicleGroup::kNone;          // its own: host::ModelCloud
};

// Files and directories (their mesh files) to loaded meshes, each with the
// class its folder or name gives (class_of_file). Tries every
// file; false when any input is missing or holds no mesh, a file won't load
// or has a bad name (empty, too long, a second file with the same stem):
// then *error has one line per such input or file, naming it, and a last
// line "N of M meshes unreadable".
bool load_model_meshes(const std::vector<std::string>& inputs, std::vector<ModelMesh>* out,
                       std::string* error, bool quiet);

// Scans every mesh from the model viewpoints; spacing is metres between rays at the object.
bool scan_models(const std::vector<ModelMesh>& meshes, double spacing, std::vector<host::ModelCloud>* out,
                 std::string* error, bool quiet);

}  // namespace spinhash::pipeline
