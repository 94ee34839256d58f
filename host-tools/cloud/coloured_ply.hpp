// Coloured point clouds for any viewer (CloudCompare, MeshLab, Open3D):
// binary little-endian PLY, one vertex element of double x y z (georeferenced
// coordinates keep their millimetres) and uchar red green blue.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// xyz: 3 per point; rgb: 3 per point. Written atomically; false with *error.
bool write_coloured_ply(const std::string& path, const std::vector<double>& xyz,
                        const std::vector<uint8_t>& rgb, std::string* error);

}  // namespace spinhash::host
