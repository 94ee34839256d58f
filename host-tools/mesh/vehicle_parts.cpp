#include "mesh/vehicle_parts.hpp"

#include <cmath>
#include <utility>

namespace spinhash::host {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr std::size_t kMinRingSize = 3;
constexpr uint32_t kMinCylinderSegments = 3;
// Fraction of the hexagon length taken by each cut corner.
constexpr double kHexagonCornerCut = 0.25;

// Flips every triangle of a closed part whose signed volume is negative, so
// the construction order of a ring does not decide the winding.
void orient_outward(Mesh* part) {
  if (part->signed_volume() >= 0.0) return;
  for (std::size_t t = 0; t < part->triangle_count(); ++t) {
    std::swap(part->triangles[3 * t + 1], part->triangles[3 * t + 2]);
  }
}

}  // namespace

void add_loft(Mesh* mesh, const std::vector<Eigen::Vector3d>& ring_a,
              const std::vector<Eigen::Vector3d>& ring_b) {
  const std::size_t n = ring_a.size();
  if (n < kMinRingSize || ring_b.size() != n) return;
  Mesh part;
  for (const auto& p : ring_a) part.add_vertex(p);
  for (const auto& p : ring_b) part.add_vertex(p);
  const auto a = [](std::size_t i) { return static_cast<uint32_t>(i); };
  const auto b = [n](std::size_t i) { return static_cast<uint32_t>(n + i); };
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    part.add_triangle(a(i), a(j), b(j));
    part.add_triangle(a(i), b(j), b(i));
  }
  // Caps use each ring edge in the direction opposite to the sides.
  for (std::size_t i = 1; i + 1 < n; ++i) {
    part.add_triangle(a(0), a(i + 1), a(i));
    part.add_triangle(b(0), b(i), b(i + 1));
  }
  orient_outward(&part);
  mesh->append(part);
}

void add_box(Mesh* mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const std::vector<Eigen::Vector3d> bottom = {
      {lo.x(), lo.y(), lo.z()}, {hi.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), lo.z()}, {lo.x(), hi.y(), lo.z()}};
  std::vector<Eigen::Vector3d> top = bottom;
  for (auto& p : top) p.z() = hi.z();
  add_loft(mesh, bottom, top);
}

void add_profile_prism(Mesh* mesh, const std::vector<ProfilePoint>& profile, double y_center) {
  std::vector<Eigen::Vector3d> left;
  std::vector<Eigen::Vector3d> right;
  for (const ProfilePoint& p : profile) {
    left.emplace_back(p.x, y_center + p.half_width, p.z);
    right.emplace_back(p.x, y_center - p.half_width, p.z);
  }
  add_loft(mesh, left, right);
}

void add_cylinder(Mesh* mesh, const Eigen::Vector3d& center, Axis axis, double radius, double length,
                  uint32_t segments) {
  if (segments < kMinCylinderSegments) segments = kMinCylinderSegments;
  // (u, v, w): two directions across the axis and the axis itself.
  const int w = axis == Axis::kX ? 0 : (axis == Axis::kY ? 1 : 2);
  const int u = (w + 1) % 3;
  const int v = (w + 2) % 3;
  std::vector<Eigen::Vector3d> ring_a;
  std::vector<Eigen::Vector3d> ring_b;
  for (uint32_t s = 0; s < segments; ++s) {
    const double angle = kTwoPi * s / segments;
    Eigen::Vector3d p = center;
    p[u] += radius * std::cos(angle);
    p[v] += radius * std::sin(angle);
    p[w] -= 0.5 * length;
    ring_a.push_back(p);
    p[w] += length;
    ring_b.push_back(p);
  }
  add_loft(mesh, ring_a, ring_b);
}

void add_plan_frustum(Mesh* mesh, const std::vector<Eigen::Vector2d>& plan, const Eigen::Vector2d& center_xy,
                      double z0, double z1, double top_scale) {
  std::vector<Eigen::Vector3d> bottom;
  std::vector<Eigen::Vector3d> top;
  for (const Eigen::Vector2d& q : plan) {
    bottom.emplace_back(center_xy.x() + q.x(), center_xy.y() + q.y(), z0);
    top.emplace_back(center_xy.x() + top_scale * q.x(), center_xy.y() + top_scale * q.y(), z1);
  }
  add_loft(mesh, bottom, top);
}

std::vector<Eigen::Vector2d> hexagon_plan(double length, double width) {
  const double hx = 0.5 * length;
  const double hy = 0.5 * width;
  const double cut = kHexagonCornerCut * length;
  return {{hx, 0.0}, {hx - cut, hy}, {-hx + cut, hy}, {-hx, 0.0}, {-hx + cut, -hy}, {hx - cut, -hy}};
}

}  // namespace spinhash::host
