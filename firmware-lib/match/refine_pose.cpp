#include "match/refine_pose.hpp"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace spinhash {
namespace {

using Vector6f = Eigen::Matrix<float, 6, 1>;
using Matrix6f = Eigen::Matrix<float, 6, 6>;

// Normal equations of the point-to-plane residuals r = n . (x - p) for a
// small motion x -> x + w x x + v of the query features in the model frame:
// dr / d(w, v) = (x x n, n).
struct PlaneSums {
  Matrix6f jtj = Matrix6f::Zero();
  Vector6f jtr = Vector6f::Zero();
  uint32_t matches = 0;
  void add(const Eigen::Vector3f& x, const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    Vector6f j;
    j.head<3>() = x.cross(n);
    j.tail<3>() = n;
    const float r = n.dot(x - p);
    // The lower triangle only: the LLT reads no other.
    for (int row = 0; row < 6; ++row) {
      for (int col = 0; col <= row; ++col) jtj(row, col) += j[row] * j[col];
      jtr[row] += j[row] * r;
    }
    ++matches;
  }
};

}  // namespace

bool refine_pose(const Database& db, uint32_t model, const QueryFeatures& query, const LikelihoodParams& lp,
                 RigidPose* pose, const int32_t* matches, float damping) {
  const blob::ModelRecord& rec = db.model(model);
  const Eigen::Matrix3f rt = pose->rotation.transpose();
  PlaneSums sums;
  for (uint32_t l = 0; l < query.count; ++l) {
    Eigen::Vector3f x, qn;
    query_in_model_frame(query, l, rt, pose->translation, &x, &qn);
    const int32_t match = matches != nullptr
                              ? matches[l]
                              : match_within_delta(find_nearest_model_feature(db, rec, x, qn, lp), lp);
    if (match == kNoMatch) continue;
    const OrientedPoint m = model_feature_point(db, static_cast<uint32_t>(match));
    sums.add(x, m.p, m.n);
  }
  if (sums.matches < kMinRefineMatches) return false;
  sums.jtj.diagonal().array() += damping * static_cast<float>(sums.matches);
  const Vector6f step = sums.jtj.llt().solve(-sums.jtr);
  if (!step.allFinite()) return false;
  const Eigen::Vector3f w = step.head<3>();
  const float angle = w.norm();
  const Eigen::Matrix3f turn =
      angle > 0.0f ? Eigen::AngleAxisf(angle, w / angle).toRotationMatrix() : Eigen::Matrix3f::Identity();
  // Model-frame motion x -> turn x + v; the pose maps model to query: q = R x + t.
  RigidPose refined;
  refined.rotation = pose->rotation * turn.transpose();
  refined.translation = pose->translation - refined.rotation * step.tail<3>();
  if (!refined.rotation.allFinite() || !refined.translation.allFinite()) return false;
  *pose = refined;
  return true;
}

RigidPose turned_end_to_end(const RigidPose& pose, const blob::ModelRecord& model) {
  // x -> T (x - c) + c in the model frame, T = diag(-1, -1, 1), c the box's
  // centre on the ground plane: q = R T x + t + R (c - T c), c - T c = (2 cx, 2 cy, 0).
  const float cx = 0.5f * (model.bbox_min[0] + model.bbox_max[0]);
  const float cy = 0.5f * (model.bbox_min[1] + model.bbox_max[1]);
  RigidPose out = pose;
  out.rotation.col(0) = -pose.rotation.col(0);
  out.rotation.col(1) = -pose.rotation.col(1);
  out.translation += (2.0f * cx) * pose.rotation.col(0) + (2.0f * cy) * pose.rotation.col(1);
  return out;
}

bool end_aligned_pose(const RigidPose& pose, const blob::ModelRecord& source, const blob::ModelRecord& target,
                      uint32_t index, RigidPose* out, float min_end_shift) {
  const bool front = index >= 2u, turned = (index & 1u) != 0u;
  const float rear_dx = source.bbox_min[0] - target.bbox_min[0];
  const float dx = front ? source.bbox_max[0] - target.bbox_max[0] : rear_dx;
  // Front ends aligned as the rear ends were: pose 0 once more.
  if (front && !turned && std::fabs(dx - rear_dx) < min_end_shift) return false;
  // x -> x + dx in the target's frame: q = R (x + dx e_x) + t.
  *out = pose;
  out->translation += dx * pose.rotation.col(0);
  if (turned) *out = turned_end_to_end(*out, target);
  return true;
}

}  // namespace spinhash
