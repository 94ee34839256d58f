// PLY body reading for the point-cloud reader: the x y z of the vertex
// element as double; every other property and element is skipped by its
// declared type, but still checked against the bytes present.
#pragma once

#include "cloud/ply_header.hpp"

#include <string>
#include <vector>

namespace spinhash::host::ply {

bool read_body(const std::string& bytes, const Header& header, std::vector<double>* xyz, std::string* error);

}  // namespace spinhash::host::ply
