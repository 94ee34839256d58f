// Query point clouds: LAS 1.0-1.4 (cloud/las_reader.hpp), PLY (ascii,
// binary little/big endian; vertex x y z float or double, everything else
// skipped) and plain "x y z" text. Compressed and foreign formats (LAZ, E57,
// PCD, gzip, zip) are refused with how to convert them.
//
// Library choice: Assimp reads the meshes, but its ai_real is float, which
// loses decimetres at UTM coordinates (4,000,000 m), and Debian packages no
// PLY library; so this is a narrow, vertex-only reader in double, hardened
// against malformed files (every header field validated, counts bounded by
// the bytes present, truncation and trailing data detected).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// Largest cloud file read (it is read whole into memory).
constexpr uint64_t kMaxCloudFileBytes = 4ull << 30;

// The path that means standard input ("-"), and the name such a cloud goes by.
constexpr const char* kStdinPath = "-";
constexpr const char* kStdinName = "stdin";

// The name of a cloud in JSON and messages: the file stem, or "stdin" for "-".
std::string cloud_name(const std::string& path);

// Reads x y z per point ("-": all of standard input, binary, up to
// kMaxCloudFileBytes). A file starting with "LASF" is LAS, one starting
// with the "ply" line PLY, anything else text. NaN coordinates are passed through (the recognizer
// drops and counts them). A PLY with zero vertices is valid and gives an
// empty cloud; a text file without a point is an error. Returns false with
// *error for anything malformed; never throws.
bool read_cloud(const std::string& path, std::vector<double>* xyz, std::string* error);

// The same on bytes already in memory (fuzzing, embedded data).
bool parse_cloud(const std::string& bytes, std::vector<double>* xyz, std::string* error);

// Reads a pose written by write_pose: 16 numbers, row-major 4x4, whose last
// row must be 0 0 0 1.
bool read_pose(const std::string& path, Eigen::Matrix4d* pose, std::string* error);

// Reads a whole file; false with *error if missing, not a regular file, or
// larger than max_bytes.
bool read_file_bytes(const std::string& path, uint64_t max_bytes, std::string* bytes, std::string* error);

}  // namespace spinhash::host
