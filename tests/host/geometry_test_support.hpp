// Helpers shared by the host geometry tests (mesh, scan, cloud).
#pragma once

#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

namespace spinhash::host::test {

// A fresh directory under the system temp dir, removed with its contents.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    std::random_device entropy;
    path_ = std::filesystem::temp_directory_path() / ("spinhash-" + tag + "-" + std::to_string(entropy()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Distance from p to the surface of the axis-aligned box [lo, hi].
inline double distance_to_box_surface(const Eigen::Vector3d& p, const Eigen::Vector3d& lo,
                                      const Eigen::Vector3d& hi) {
  const Eigen::Vector3d outside = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
  if (outside.norm() > 0.0) return outside.norm();
  const Eigen::Vector3d inside = (p - lo).cwiseMin(hi - p);
  return inside.minCoeff();
}

// Distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
inline double distance_to_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

// Brute-force distance from p to the nearest triangle of mesh.
inline double distance_to_mesh(const Eigen::Vector3d& p, const Mesh& mesh) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    best = std::min(best, distance_to_triangle(p, mesh.vertex(mesh.triangles[3 * t]),
                                               mesh.vertex(mesh.triangles[3 * t + 1]),
                                               mesh.vertex(mesh.triangles[3 * t + 2])));
  }
  return best;
}

}  // namespace spinhash::host::test
