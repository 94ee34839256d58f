#include "match/pose_from_doublet.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

namespace spinhash {

bool pose_from_doublet(const OrientedPoint& q1, const OrientedPoint& q2, const OrientedPoint& m1,
                       const OrientedPoint& m2, RigidPose* out, float normal_lever) {
  constexpr int kPairs = 4;
  const Eigen::Vector3f qs[kPairs] = {q1.p, q2.p, q1.p + normal_lever * q1.n, q2.p + normal_lever * q2.n};
  const Eigen::Vector3f ms[kPairs] = {m1.p, m2.p, m1.p + normal_lever * m1.n, m2.p + normal_lever * m2.n};
  Eigen::Vector3f qc = Eigen::Vector3f::Zero(), mc = Eigen::Vector3f::Zero();
  for (int i = 0; i < kPairs; ++i) {
    qc += qs[i];
    mc += ms[i];
  }
  qc /= static_cast<float>(kPairs);
  mc /= static_cast<float>(kPairs);
  Eigen::Matrix3f h = Eigen::Matrix3f::Zero();
  for (int i = 0; i < kPairs; ++i) h.noalias() += (ms[i] - mc) * (qs[i] - qc).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3f> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3f& sv = svd.singularValues();
  if (!(sv(1) > 1e-6f * sv(0))) return false;  // rank < 2: rotation undetermined
  Eigen::Matrix3f v = svd.matrixV(), u = svd.matrixU();
  float det = (v * u.transpose()).determinant();
  Eigen::Vector3f fix(1.0f, 1.0f, det < 0.0f ? -1.0f : 1.0f);  // a rotation, never a reflection
  out->rotation = v * fix.asDiagonal() * u.transpose();
  out->translation = qc - out->rotation * mc;
  return out->rotation.allFinite() && out->translation.allFinite();
}

}  // namespace spinhash
