// PLY body reading for the point-cloud reader: the x y z of the vertex
// element as double; every other property and element is skipped by its
// declared type, but still checked against the bytes present.
#pragma once

#include "cloud/ply_header.hpp"

#include <string>
#include <vector>

namespace spinhash::host::ply {

bool read_body(const std::string& bytes, const Header& header, std::vector<double>* xyz, std::string* error);

// A mesh: the vertices' x y z as above, and the face element's index lists
// (property vertex_indices or vertex_index) as they are, each one's count
// first, then its indices: "3 0 1 2 4 0 2 3 5 ...". False with *error when
// there is no face element; index values are not checked here.
bool read_mesh_body(const std::string& bytes, const Header& header, std::vector<double>* xyz,
                    std::vector<double>* faces, std::string* error);

// The value of a binary property of `type` at p, in the file's byte order
// (the chunked reader of cloud/point_source.cpp decodes records with it).
double binary_value(Type type, const unsigned char* p, bool big_endian);

}  // namespace spinhash::host::ply
