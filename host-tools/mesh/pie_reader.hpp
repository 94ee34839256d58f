// Warzone 2100 PIE models (text, versions 2, 3 and 4) to a Mesh.
//
// Why a reader of our own: Assimp does not read PIE, and Debian's
// warzone2100-data package is the source of real artist-made rigid models
// (vehicle bodies, propulsion, structures) for the experiments. The reader
// is deliberately narrow: geometry only, the POINTS and POLYGONS of every
// LEVEL (levels are separate parts of one model, e.g. a factory's modules),
// polygons fanned into triangles. Textures, animation, connectors, normals,
// shadow and event data are skipped, as is any section it does not know.
#pragma once

#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <istream>
#include <string>

namespace spinhash::host {

// Bounds that keep a hostile file from exhausting memory.
constexpr uint32_t kMaxPiePoints = 1u << 20;    // per level
constexpr uint32_t kMaxPiePolygons = 1u << 20;  // per level
constexpr uint32_t kMaxPiePolygonVertices = 64;
constexpr uint64_t kMaxPieFileBytes = 64u << 20;

// Warzone world units to metres. The game is not to scale; at 0.075 m per
// unit (a 128-unit map tile is 9.6 m) the droids come out vehicle-sized:
// light wheeled 4.5 x 4.9 x 1.6 m, heavy tracked 6.2 x 7.0 x 2.6 m,
// the school bus 8.8 m long, the jeep 3.7 m.
constexpr double kPieMetresPerUnit = 0.075;

struct PieInfo {
  uint32_t version = 0;  // 2, 3 or 4
  uint32_t levels = 0;
  uint32_t polygons = 0;
};

// Parses PIE text; the mesh is in PIE coordinates (units, y up). false with
// *error (naming the line) on anything malformed.
bool parse_pie(std::istream& in, Mesh* out, PieInfo* info, std::string* error);
// Reads a file; out->name is the file stem.
bool read_pie(const std::string& path, Mesh* out, PieInfo* info, std::string* error);

// PIE (x right, y up, z along the model, units) to the generator's frame
// (x forward, y left, z up, metres): the rotation (x, y, z) -> (z, x, y)
// scaled by kPieMetresPerUnit, a proper rotation, so nothing is mirrored.
Eigen::Matrix4d pie_to_metres();

}  // namespace spinhash::host
