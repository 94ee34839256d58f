#include "mesh/mesh.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace spinhash::host {

uint32_t Mesh::add_vertex(const Eigen::Vector3d& p) {
  const auto index = static_cast<uint32_t>(vertex_count());
  vertices.push_back(static_cast<float>(p.x()));
  vertices.push_back(static_cast<float>(p.y()));
  vertices.push_back(static_cast<float>(p.z()));
  return index;
}

void Mesh::add_triangle(uint32_t a, uint32_t b, uint32_t c) {
  triangles.push_back(a);
  triangles.push_back(b);
  triangles.push_back(c);
}

Box3 Mesh::bounding_box() const {
  Box3 box;
  for (std::size_t i = 0; i < vertex_count(); ++i) {
    const Eigen::Vector3d p = vertex(i);
    if (i == 0) {
      box.lo = p;
      box.hi = p;
    } else {
      box.lo = box.lo.cwiseMin(p);
      box.hi = box.hi.cwiseMax(p);
    }
  }
  return box;
}

double Mesh::surface_area() const {
  double area = 0.0;
  for (std::size_t t = 0; t < triangle_count(); ++t) {
    const Eigen::Vector3d a = vertex(triangles[3 * t]);
    const Eigen::Vector3d b = vertex(triangles[3 * t + 1]);
    const Eigen::Vector3d c = vertex(triangles[3 * t + 2]);
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

double Mesh::signed_volume() const {
  double volume = 0.0;
  for (std::size_t t = 0; t < triangle_count(); ++t) {
    const Eigen::Vector3d a = vertex(triangles[3 * t]);
    const Eigen::Vector3d b = vertex(triangles[3 * t + 1]);
    const Eigen::Vector3d c = vertex(triangles[3 * t + 2]);
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

void Mesh::apply_transform(const Eigen::Matrix4d& transform) {
  const Eigen::Affine3d affine(transform);
  for (std::size_t i = 0; i < vertex_count(); ++i) {
    const Eigen::Vector3d p = affine * vertex(i);
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(p[k]);
  }
  if (affine.linear().determinant() < 0.0) {
    for (std::size_t t = 0; t < triangle_count(); ++t) {
      std::swap(triangles[3 * t + 1], triangles[3 * t + 2]);
    }
  }
}

void Mesh::append(const Mesh& other) {
  const auto base = static_cast<uint32_t>(vertex_count());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (uint32_t index : other.triangles) triangles.push_back(base + index);
}

std::string Mesh::validate() const {
  if (vertices.size() % 3 != 0) return "vertex array size is not a multiple of 3";
  if (triangles.size() % 3 != 0) return "triangle array size is not a multiple of 3";
  for (float v : vertices) {
    if (!std::isfinite(v)) return "mesh has a non-finite vertex coordinate";
  }
  const std::size_t n = vertex_count();
  for (uint32_t index : triangles) {
    if (index >= n) return "triangle index out of range";
  }
  return {};
}

}  // namespace spinhash::host
