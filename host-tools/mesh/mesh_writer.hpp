// Writes meshes for inspection and for other tools: Wavefront OBJ (text) and
// binary little-endian PLY. Both atomically (PATH.tmp, then rename).
#pragma once

#include "mesh/mesh.hpp"

#include <string>

namespace spinhash::host {

bool write_obj(const std::string& path, const Mesh& mesh, std::string* error);
bool write_mesh_ply(const std::string& path, const Mesh& mesh, std::string* error);
// By extension: ".obj" or ".ply" (case-insensitive); anything else is an error.
bool write_mesh(const std::string& path, const Mesh& mesh, std::string* error);

}  // namespace spinhash::host
