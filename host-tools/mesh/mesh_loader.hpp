// Loads model meshes into one merged triangle mesh: PLY through the project's
// own reader (mesh/ply_mesh_reader.hpp), every other format Assimp reads (OBJ,
// STL, OFF, glTF, Collada, AC3D, ...) through Assimp.
#pragma once

#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace spinhash::host {

// Loads every mesh of the scene with node transforms applied, triangulated
// and merged; point and line primitives are dropped, unused vertices
// removed. out->name is the file stem. Returns false with *error set when the
// file is missing, unreadable or corrupt, has no triangles, has non-finite
// vertices or has zero surface area. Never throws.
bool load_mesh(const std::string& path, Mesh* out, std::string* error);

// A file gives itself; a directory gives its regular files (non-recursive,
// hidden files skipped) whose extension Assimp supports, sorted by name.
// Returns an empty list with *error set when the path does not exist or a
// directory holds no mesh file.
std::vector<std::string> list_mesh_files(const std::string& path_or_dir, std::string* error);

}  // namespace spinhash::host
