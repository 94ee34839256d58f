// Convex building blocks of the procedural vehicles. Each call appends one
// closed surface (its own vertices, no sharing with other parts) wound so
// that normals point outward. Parts may overlap: a scan sees only the outer
// skin, as on a real vehicle whose wheels sit partly inside the body.
#pragma once

#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace spinhash::host {

enum class Axis { kX, kY, kZ };

// Closed solid between two rings of equal size (>= 3): side quads join
// ring_a[i] to ring_b[i], each ring is closed by a fan. Both rings must be
// convex and traversed in the same rotational sense.
void add_loft(Mesh* mesh, const std::vector<Eigen::Vector3d>& ring_a,
              const std::vector<Eigen::Vector3d>& ring_b);

void add_box(Mesh* mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

// One vertex of a side profile: position in the x-z plane and the half width
// (y) of the solid at that vertex, which gives tumblehome and tapered noses.
struct ProfilePoint {
  double x;
  double z;
  double half_width;
};

// Prism symmetric about y = y_center whose cross-section in x-z is the convex
// polygon `profile` (counter-clockwise seen from +y, i.e. x right, z up).
void add_profile_prism(Mesh* mesh, const std::vector<ProfilePoint>& profile, double y_center = 0.0);

// Closed cylinder (regular polygon of `segments` sides) centred at `center`.
void add_cylinder(Mesh* mesh, const Eigen::Vector3d& center, Axis axis, double radius, double length,
                  uint32_t segments);

// Upright frustum with a convex plan polygon (x, y relative to center_xy,
// counter-clockwise from above) from z0 to z1, the top scaled by top_scale.
void add_plan_frustum(Mesh* mesh, const std::vector<Eigen::Vector2d>& plan, const Eigen::Vector2d& center_xy,
                      double z0, double z1, double top_scale);

// Regular hexagonal plan with the given length (x) and width (y): the
// corners at +-x are cut so it reads as a turret.
std::vector<Eigen::Vector2d> hexagon_plan(double length, double width);

}  // namespace spinhash::host
