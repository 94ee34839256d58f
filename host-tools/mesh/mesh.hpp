// A triangle mesh in plain arrays: the host-side model surface that loaders
// produce, the vehicle generator builds and the scan simulator ray-casts.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// Axis-aligned box; empty (lo > hi) for a mesh without vertices.
struct Box3 {
  Eigen::Vector3d lo{1.0, 1.0, 1.0};
  Eigen::Vector3d hi{-1.0, -1.0, -1.0};

  bool empty() const { return (lo.array() > hi.array()).any(); }
  Eigen::Vector3d center() const { return 0.5 * (lo + hi); }
  Eigen::Vector3d size() const { return hi - lo; }
};

struct Mesh {
  std::string name;
  std::vector<float> vertices;      // x y z per vertex
  std::vector<uint32_t> triangles;  // 3 vertex indices per triangle

  std::size_t vertex_count() const { return vertices.size() / 3; }
  std::size_t triangle_count() const { return triangles.size() / 3; }
  Eigen::Vector3d vertex(std::size_t i) const {
    return {vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]};
  }

  // Appends one vertex and returns its index.
  uint32_t add_vertex(const Eigen::Vector3d& p);
  void add_triangle(uint32_t a, uint32_t b, uint32_t c);

  Box3 bounding_box() const;
  double surface_area() const;
  // Signed volume by the divergence theorem: positive for closed surfaces
  // wound counter-clockwise seen from outside.
  double signed_volume() const;

  // Applies a rigid or affine transform to every vertex. A mirroring
  // transform (negative determinant) also flips the winding, so outward
  // normals stay outward.
  void apply_transform(const Eigen::Matrix4d& transform);
  // Adds other's vertices and triangles (indices shifted); keeps this name.
  void append(const Mesh& other);

  // Empty string when arrays are well formed: sizes multiples of 3,
  // indices in range, every coordinate finite.
  std::string validate() const;
};

}  // namespace spinhash::host
