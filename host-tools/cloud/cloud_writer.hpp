// Writes query point clouds and poses, atomically (PATH.tmp, then rename).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// PLY with one vertex element of double x y z: binary_little_endian (on any
// host) or ascii with 17 significant digits; both round-trip exactly.
bool write_ply(const std::string& path, const std::vector<double>& xyz, bool binary, std::string* error);

// The point-cloud formats written, chosen by the file's extension.
enum class CloudFormat { kPly, kLas, kUnknown };
CloudFormat cloud_format_for(const std::string& path);  // ".ply" / ".las", any case

// PLY (binary unless ascii) or LAS 1.2 (classification per point, or none),
// by the extension; an unknown extension is an error naming the choices.
bool write_cloud(const std::string& path, const std::vector<double>& xyz,
                 const std::vector<uint8_t>& classification, bool ascii, std::string* error);

// 4 lines of 4 numbers (%.17g), row-major: read back exactly by read_pose.
bool write_pose(const std::string& path, const Eigen::Matrix4d& pose, std::string* error);

}  // namespace spinhash::host
