#include "match/doublet.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "util/angle_math.hpp"

namespace spinhash {
namespace {
constexpr float kMinSeparation = 1e-6f;  // m: coincident points give no direction
}

bool doublet_shape(const OrientedPoint& x1, const OrientedPoint& x2, DoubletShape* out) {
  Eigen::Vector3f delta = x2.p - x1.p;
  float d = delta.norm();
  if (!(d > kMinSeparation)) return false;
  Eigen::Vector3f u = delta / d;
  out->d = d;
  out->a = safe_acos(x1.n.dot(x2.n));
  out->b = safe_acos(x1.n.dot(u));
  out->c = safe_acos(x2.n.dot(u));
  out->t = x1.n.cross(x2.n).dot(u);
  return true;
}

CascadeStage check_doublet(const DoubletShape& q, const OrientedPoint& m1, const OrientedPoint& m2,
                           const DoubletTolerance& tol) {
  const Eigen::Vector3f delta = m2.p - m1.p;
  const float d = delta.norm();
  if (!separation_agrees(q, d, tol)) return CascadeStage::kDistance;
  return check_doublet_normals(q, m1.n, m2.n, delta, d, tol);
}

CascadeStage check_doublet_normals(const DoubletShape& q, const Eigen::Vector3f& n1,
                                   const Eigen::Vector3f& n2, const Eigen::Vector3f& delta, float d,
                                   const DoubletTolerance& tol) {
  if (!(d > kMinSeparation)) return CascadeStage::kDegenerate;
  if (std::fabs(safe_acos(n1.dot(n2)) - q.a) > tol.angle) return CascadeStage::kAngleA;
  const Eigen::Vector3f u = delta / d;
  if (std::fabs(safe_acos(n1.dot(u)) - q.b) > tol.angle) return CascadeStage::kAngleB;
  if (std::fabs(safe_acos(n2.dot(u)) - q.c) > tol.angle) return CascadeStage::kAngleC;
  if (std::fabs(n1.cross(n2).dot(u) - q.t) > tol.handedness) return CascadeStage::kHandedness;
  return CascadeStage::kPass;
}

}  // namespace spinhash
