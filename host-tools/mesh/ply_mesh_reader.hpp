// PLY meshes through the project's own PLY reader (cloud/ply_header,
// cloud/ply_body) instead of Assimp: Debian 12's Assimp 5.2.5 drops a
// line-end byte at the start of a binary body ('\n' or '\r' as the first
// byte of the first x), shifting every value after it ("mIndices[0] is out of
// range"), about 4 in 1000 generated meshes. Ascii and binary, either byte
// order; polygons fanned into triangles; points and lines dropped.
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace spinhash::host {

// The triangles of the PLY file at path with the vertices they use, as
// load_mesh gives them. False with *error for a malformed file, a face index
// out of range or not an integer, or a non-finite used vertex; the triangle
// count and area checks are load_mesh's. Never throws.
bool read_ply_mesh(const std::string& path, Mesh* out, std::string* error);

}  // namespace spinhash::host
