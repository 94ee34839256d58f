// Writes LAS 1.2, point data format 1 (x y z, intensity 0, classification,
// GPS time: given or 0): the format every lidar tool reads. Coordinates are stored as
// 32-bit integers at kLasWriteScale with the offset at the cloud's floored
// minimum, so georeferenced clouds keep millimetres.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

constexpr double kLasWriteScale = 0.001;  // m per integer step

// xyz: 3 per point; classification: one per point or empty (class 1,
// "unclassified"). False with *error when a coordinate is not finite or does
// not fit the 32-bit range at that scale (2 147 km from the offset).
bool las_bytes(const std::vector<double>& xyz, const std::vector<uint8_t>& classification, std::string* out,
               std::string* error);

// The same with a GPS time per point (seconds; empty: 0 for every point).
bool las_bytes(const std::vector<double>& xyz, const std::vector<uint8_t>& classification,
               const std::vector<double>& gps_time, std::string* out, std::string* error);

// The same, written to `path` atomically (nothing is left behind on failure).
bool write_las(const std::string& path, const std::vector<double>& xyz,
               const std::vector<uint8_t>& classification, std::string* error);
bool write_las(const std::string& path, const std::vector<double>& xyz,
               const std::vector<uint8_t>& classification, const std::vector<double>& gps_time,
               std::string* error);

}  // namespace spinhash::host
