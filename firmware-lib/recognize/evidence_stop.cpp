// BRAN's stop on evidence: RANSAC's termination bound (Fischler and Bolles;
// adaptive RANSAC) for doublets drawn from the joint candidates. A draw leads
// to the leading model's pose when both of its query features hold a
// candidate of that model lying, under that pose, within Delta of them: with
// q the draws' (saliency-weighted) share of such features, a draw misses with
// probability 1 - q^2, and after n draws all of them missed with (1 - q^2)^n.
// Once that is below stop_miss_probability, more draws would most likely
// only find the same pose again; models near the leader are still reached by
// the pose transfer and the final rescoring. A wrong leader fits few
// candidates, so its q is small and the search goes on to the budget.
#include "recognize/evidence_stop.hpp"

namespace spinhash {
namespace {

// The bound is consulted after DrawsParams::min_evidence_draws: q from one
// early pose is noisy, and the first correct doublets give poses degrees off.
// (1 - q^2)^n below this is taken as 0 (no float underflow on any target).
constexpr float kNegligibleMiss = 1.0e-20f;

// Query feature l holds a candidate of `model` that `pose` puts within Delta of it.
bool has_fitting_candidate(const SearchContext& ctx, uint32_t model, const RigidPose& pose, uint32_t l) {
  const Candidate* c = ctx.candidates_of(l);
  const uint16_t* models = ctx.db.feature_models();
  const float* q = ctx.query.positions + 3u * l;
  const Eigen::Vector3f at(q[0], q[1], q[2]);
  for (uint32_t u = 0; u < ctx.buf.candidate_count[l]; ++u) {
    if (models[c[u].feature] != model) continue;
    const float* p = ctx.db.positions() + 3u * c[u].feature;
    const Eigen::Vector3f x = pose.rotation * Eigen::Vector3f(p[0], p[1], p[2]) + pose.translation;
    if ((x - at).squaredNorm() <= ctx.likelihood.delta2) return true;
  }
  return false;
}

// q: the draw weight of the features whose candidates fit the model's pose.
float fitting_draw_share(const SearchContext& ctx, uint32_t model) {
  const RigidPose& pose = ctx.buf.best[model].pose;
  float fitting = 0.0f, previous = 0.0f;
  for (uint32_t l = 0; l < ctx.query.count; ++l) {
    const float weight = ctx.cumulative[l] - previous;
    previous = ctx.cumulative[l];
    if (weight > 0.0f && has_fitting_candidate(ctx, model, pose, l)) fitting += weight;
  }
  return previous > 0.0f ? fitting / previous : 0.0f;
}

// base^n by squaring (multiplications only: the same on every target).
float power(float base, uint32_t n) {
  float result = 1.0f;
  while (n > 0u && result > kNegligibleMiss) {
    if (n & 1u) result *= base;
    base *= base;
    n >>= 1u;
  }
  return result;
}

}  // namespace

void note_leader(SearchContext& ctx, uint32_t model) {
  EvidenceState& e = ctx.evidence;
  const float score = ctx.buf.best[model].score;
  if (e.leader != kNoLeader && !(score > e.leader_score)) return;
  e.leader = model;
  e.leader_score = score;
  e.leader_moved = true;
}

bool evidence_says_stop(SearchContext& ctx) {
  EvidenceState& e = ctx.evidence;
  const DrawsParams& d = ctx.params.draws;
  if (d.stop_miss_probability <= 0.0f || e.leader == kNoLeader || ctx.cumulative == nullptr) return false;
  if (e.leader_moved) {
    const float q = fitting_draw_share(ctx, e.leader);
    e.miss_per_draw = 1.0f - q * q;
    e.leader_moved = false;
  }
  return e.draws >= d.min_evidence_draws && power(e.miss_per_draw, e.draws) <= d.stop_miss_probability;
}

}  // namespace spinhash
