#include "query_runner.hpp"
#include "spinhash/answered.hpp"

#include <algorithm>

namespace spinhash::experiment {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

void pose_errors(const Pose& p, const Eigen::Matrix4d& truth, Outcome* o) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = p.rotation[3 * i + j];
  const Eigen::Matrix3d d = truth.topLeftCorner<3, 3>().transpose() * r;
  o->rotation_error_deg = std::acos(std::clamp((d.trace() - 1.0) / 2.0, -1.0, 1.0)) * kRadToDeg;
  const Eigen::Vector3d t(p.translation[0], p.translation[1], p.translation[2]);
  o->translation_error_m = (t - truth.topRightCorner<3, 1>()).norm();
}

}  // namespace

Outcome recognise(pipeline::RecognitionSession& session, const Query& q) {
  Result r = session.recognize(q.xyz);
  Outcome o;
  o.status = r.status;
  o.ms = session.last_ms();
  o.hypotheses = r.stats.draws.hypotheses;
  o.features = r.stats.extract.features;
  o.confident = r.confident;
  o.group_size = r.group_size;
  o.budget_exhausted = r.stats.draws.budget_exhausted;
  o.trials = r.stats.draws.trials;
  o.surface_coverage = r.stats.confidence.surface_coverage;
  o.scan_density = r.stats.confidence.scan_density;
  if (!has_answer(r.status)) return o;
  o.ranked = r.ranking_count;
  if (r.ranking_count > 0) {
    o.best_model = r.ranking[0].model;
    o.score_first = r.ranking[0].score;
    o.inliers = r.ranking[0].inliers;
    if (r.ranking[0].has_pose) pose_errors(r.ranking[0].pose, q.true_pose, &o);
  }
  if (r.class_ranking_count > 0) o.class_first = r.class_ranking[0].vehicle_class;
  if (r.class_ranking_count > 1) o.class_lead = r.class_ranking[0].score - r.class_ranking[1].score;
  o.class_confident = r.class_confident;
  if (r.ranking_count > 1) o.score_second = r.ranking[1].score;
  for (uint32_t i = 0; i < r.ranking_count; ++i)
    if (r.ranking[i].model == q.model) {
      o.rank = i + 1u;
      break;
    }
  return o;
}

}  // namespace spinhash::experiment
