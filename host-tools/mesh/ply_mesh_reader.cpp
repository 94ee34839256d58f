#include "mesh/ply_mesh_reader.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

#include "blob/file_io.hpp"
#include "cloud/ply_body.hpp"
#include "cloud/ply_header.hpp"

namespace spinhash::host {
namespace {

constexpr uint64_t kMaxMeshFileBytes = 1ull << 31;  // read whole into memory
constexpr double kCornersPerTriangle = 3.0;

// Adds the polygons of `faces` (count, then indices) as triangle fans,
// copying each used vertex once.
bool add_faces(const std::vector<double>& xyz, const std::vector<double>& faces, Mesh* mesh,
               std::string* why) {
  const double vertices = static_cast<double>(xyz.size() / 3);
  std::unordered_map<uint64_t, uint32_t> remap;
  auto corner = [&](double index, uint32_t* out) {
    if (!(index >= 0.0 && index < vertices) || index != std::floor(index)) {
      *why = "face index " + std::to_string(index) + " out of range (" + std::to_string(xyz.size() / 3) +
             " vertices)";
      return false;
    }
    const auto i = static_cast<uint64_t>(index);
    auto found = remap.find(i);
    if (found == remap.end()) {
      const Eigen::Vector3d v(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      if (!v.cast<float>().allFinite()) {  // stored as float
        *why = "non-finite vertex coordinate";
        return false;
      }
      found = remap.emplace(i, mesh->add_vertex(v)).first;
    }
    *out = found->second;
    return true;
  };
  for (size_t at = 0; at < faces.size();) {
    const auto n = static_cast<size_t>(faces[at]);
    const size_t first = at + 1;
    at = first + n;
    if (faces[first - 1] < kCornersPerTriangle) continue;  // points and lines
    uint32_t a = 0, b = 0, c = 0;
    if (!corner(faces[first], &a) || !corner(faces[first + 1], &b)) return false;
    for (size_t k = 2; k < n; ++k, b = c) {
      if (!corner(faces[first + k], &c)) return false;
      mesh->add_triangle(a, b, c);
    }
  }
  return true;
}

}  // namespace

bool read_ply_mesh(const std::string& path, Mesh* out, std::string* error) {
  try {
    std::string bytes, why;
    if (!read_file(path, kMaxMeshFileBytes, &bytes, error)) return false;
    ply::Header header;
    std::vector<double> xyz, faces;
    Mesh mesh;
    if (!ply::parse_header(bytes, &header, &why) || !ply::read_mesh_body(bytes, header, &xyz, &faces, &why) ||
        !add_faces(xyz, faces, &mesh, &why)) {
      if (error) *error = "cannot read mesh " + path + ": " + why;
      return false;
    }
    *out = std::move(mesh);
    return true;
  } catch (const std::exception& e) {
    if (error) *error = "cannot read mesh " + path + ": " + e.what();
    return false;
  }
}

}  // namespace spinhash::host
