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
  Eigen::Vector3f delta = m2.p - m1.p;
  float d = delta.norm();
  if (std::fabs(d - q.d) > tol.distance) return CascadeStage::kDistance;
  if (!(d > kMinSeparation)) return CascadeStage::kDegenerate;
  if (std::fabs(safe_acos(m1.n.dot(m2.n)) - q.a) > tol.angle) return CascadeStage::kAngleA;
  Eigen::Vector3f u = delta / d;
  if (std::fabs(safe_acos(m1.n.dot(u)) - q.b) > tol.angle) return CascadeStage::kAngleB;
  if (std::fabs(safe_acos(m2.n.dot(u)) - q.c) > tol.angle) return CascadeStage::kAngleC;
  if (std::fabs(m1.n.cross(m2.n).dot(u) - q.t) > tol.handedness) return CascadeStage::kHandedness;
  return CascadeStage::kPass;
}

}  // namespace spinhash
