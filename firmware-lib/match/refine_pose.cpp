#include "match/refine_pose.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

#include "match/pose_from_doublet.hpp"

namespace spinhash {
namespace {

// Running sums for Kabsch without storing the pairs.
struct PairSums {
  Eigen::Vector3f sum_q = Eigen::Vector3f::Zero(), sum_m = Eigen::Vector3f::Zero();
  Eigen::Matrix3f sum_mq = Eigen::Matrix3f::Zero();
  float n = 0.0f;
  void add(const Eigen::Vector3f& m, const Eigen::Vector3f& q) {
    sum_q += q;
    sum_m += m;
    sum_mq.noalias() += m * q.transpose();
    n += 1.0f;
  }
};

}  // namespace

bool refine_pose(const Database& db, uint32_t model, const QueryFeatures& query, const LikelihoodParams& lp,
                 RigidPose* pose) {
  const blob::ModelRecord& rec = db.model(model);
  const Eigen::Matrix3f rt = pose->rotation.transpose();
  PairSums sums;
  uint32_t matches = 0;
  for (uint32_t l = 0; l < query.count; ++l) {
    Eigen::Vector3f qp(query.positions[3u * l], query.positions[3u * l + 1u], query.positions[3u * l + 2u]);
    Eigen::Vector3f qn(query.normals[3u * l], query.normals[3u * l + 1u], query.normals[3u * l + 2u]);
    NearestFeature near = find_nearest_model_feature(db, rec, rt * (qp - pose->translation), rt * qn, lp);
    if (near.feature < 0 || near.dist2 > lp.delta2) continue;
    const uint32_t f = static_cast<uint32_t>(near.feature);
    Eigen::Vector3f mp(db.positions()[3u * f], db.positions()[3u * f + 1u], db.positions()[3u * f + 2u]);
    const int16_t* mn16 = db.normals() + 3u * f;
    Eigen::Vector3f mn(decode_normal_component(mn16[0]), decode_normal_component(mn16[1]),
                       decode_normal_component(mn16[2]));
    sums.add(mp, qp);
    sums.add(mp + kNormalLever * mn, qp + kNormalLever * qn);
    ++matches;
  }
  if (matches < kMinRefineMatches) return false;
  const Eigen::Vector3f qc = sums.sum_q / sums.n, mc = sums.sum_m / sums.n;
  const Eigen::Matrix3f h = sums.sum_mq - sums.n * mc * qc.transpose();
  Eigen::JacobiSVD<Eigen::Matrix3f> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3f u = svd.matrixU(), v = svd.matrixV();
  const float det = (v * u.transpose()).determinant();
  const Eigen::Vector3f fix(1.0f, 1.0f, det < 0.0f ? -1.0f : 1.0f);
  RigidPose refined;
  refined.rotation = v * fix.asDiagonal() * u.transpose();
  refined.translation = qc - refined.rotation * mc;
  if (!refined.rotation.allFinite() || !refined.translation.allFinite()) return false;
  *pose = refined;
  return true;
}

}  // namespace spinhash
