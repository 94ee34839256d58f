// The test worlds' meshes (scripts/prepare-*.sh): put in the generator's
// frame (metres, x forward, y left, z up, ground at z = 0, footprint centred)
// and written as OBJ, one catalog.csv row each.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace spinhash::experiment {

// Ground at z = 0, footprint centred on the origin.
void settle(host::Mesh* m);
// A 4x4 transform of the 3x3 linear map r (no translation).
Eigen::Matrix4d linear_transform(const Eigen::Matrix3d& r);

class CsvTable;

// One catalog.csv row: name, class, group, source, triangles, length,
// width, height (m) of a settled mesh. The group is the vehicle's own: its
// class's (include/spinhash/vehicle_classes.h) unless `group` names one, as
// it must for an "other" vehicle whose group is known (a half-tonne buggy is
// a light vehicle, though its class spans the groups); none for clutter.
std::vector<std::string> catalog_row(const host::Mesh& m, const std::string& klass, const std::string& source,
                                     const std::string& group = "");
// The header of catalog_row.
std::vector<std::string> catalog_header();
// Writes m as OUT/<klass>/<m.name>.obj (the class folder `build` reads the
// class from) and adds its catalog row.
bool write_in_class_folder(const std::string& out, const std::string& klass, const std::string& source,
                           const host::Mesh& m, CsvTable* catalog, std::string* error,
                           const std::string& group = "");

}  // namespace spinhash::experiment
