// Whole clouds and poses, as helpers on top of the one reading door
// (cloud/point_source.hpp): every format it reads (LAS 1.0-1.4, LAZ and
// COPC, PLY, x y z text), with its errors (CloudError, naming the file).
//
// Library choice: Assimp reads the meshes, but its ai_real is float, which
// loses decimetres at UTM coordinates (4,000,000 m), and Debian packages no
// PLY library; so the cloud readers are our own, in double, hardened
// against malformed files (every header field validated, counts bounded by
// the bytes present, truncation and trailing data detected).
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "cloud/point_source.hpp"

namespace spinhash::host {

// x y z per point of the file ("-": standard input), in the file's own
// coordinates. NaN coordinates are passed through (the recognizer drops and
// counts them). A PLY with zero vertices is valid and gives an empty cloud;
// a text file without a point is an error. Throws CloudError.
std::vector<double> read_cloud(const std::string& path);
// The same on bytes already in memory (fuzzing, embedded data).
std::vector<double> read_cloud_bytes(const std::string& bytes, const std::string& name = "bytes");

// Reads a pose written by write_pose: 16 numbers, row-major 4x4, whose last
// row must be 0 0 0 1.
bool read_pose(const std::string& path, Eigen::Matrix4d* pose, std::string* error);

}  // namespace spinhash::host
