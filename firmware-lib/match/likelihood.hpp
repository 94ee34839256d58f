// Likelihood of a pose (section 8, eqs. 4-7) in log form. For every query
// feature the nearest model feature under the pose (found through the model's
// grid in the blob, by mapping the query feature into the model frame, which
// is the same as warping every model feature into the query) contributes
//   log p_o = -min(r, Delta)^2 / (2 sigma^2)  for r <= Delta_max   (eq. 5)
//   p_n     = 1 if angle(normals) <= eta_max, else the feature is not a match (eq. 6)
//   log p_s = -L1(spin images) / lambda                              (p_s of eq. 4)
// Eq. 5 gives p = 0 beyond Delta_max, so one unexplained feature would make
// the product of eq. 7 zero for every pose; in log form each feature's term is
// instead floored at the value of a match at Delta with the most dissimilar
// spin image (L1 = 2): -Delta^2 / (2 sigma^2) - 2 / lambda. The final
// ranking of the leading models measures r to the model's surface instead
// (make_surface_params, residual2).
#pragma once
#include <cstdint>

#include "kernels/nearest_geometry.hpp"
#include "match/oriented_point.hpp"
#include "spinhash/config.hpp"
#include "spinhash/database.hpp"

namespace spinhash {

struct QueryFeatures {
  const float* positions = nullptr;  // 3 per feature, query frame (re-centred)
  const float* normals = nullptr;
  const uint8_t* spins = nullptr;  // quantised with the database's scale
  uint32_t count = 0;
  uint32_t dims = 0;
  uint32_t verify_count = 0;  // features verify_pose scores (evenly spread), <= count
};

// Grid cells searched each way around a point, at most: Delta_max may span up
// to this many model-grid cells (a larger Delta_max is searched only this far).
constexpr uint32_t kMaxGridReach = 4;

// Model feature f of the blob: its position, its decoded unit normal, both.
inline Eigen::Vector3f model_feature_position(const Database& db, uint32_t f) {
  const float* p = db.positions() + 3u * f;
  return Eigen::Vector3f(p[0], p[1], p[2]);
}
inline Eigen::Vector3f model_feature_normal(const Database& db, uint32_t f) {
  const int16_t* n = db.normals() + 3u * f;
  return Eigen::Vector3f(decode_normal_component(n[0]), decode_normal_component(n[1]),
                         decode_normal_component(n[2]));
}
inline OrientedPoint model_feature_point(const Database& db, uint32_t f) {
  return OrientedPoint{model_feature_position(db, f), model_feature_normal(db, f)};
}

constexpr float kPointToPoint = -1.0f;  // LikelihoodParams::surface_patch_radius: the paper's r

struct LikelihoodParams {
  float inv_two_sigma2 = 0.0f;
  float delta2 = 0.0f;      // Delta^2
  float delta_max2 = 0.0f;  // Delta_max^2
  float cos_eta_max = 0.0f;
  float spin_weight = 0.0f;  // 1 / (lambda * quant_scale): quantised L1 -> -log p_s
  float floor = 0.0f;        // per-feature log-likelihood of an unexplained feature
  uint32_t reach = 1;        // grid cells searched each way
  bool use_field = false;    // the blob's nearest-feature field answers (it reaches Delta_max)
  // r of eq. 5: < 0, the paper's distance between the query feature and the
  // nearest model feature; >= 0, the distance to the patch of model surface
  // that feature stands for: the offset along its normal, plus how far the
  // query feature lies beyond this radius (m) along the surface.
  float surface_patch_radius = kPointToPoint;
  // Preemptive verification (DrawsParams::preemptive_*): a hypothesis is
  // first scored on preemptive_first query features (spread evenly over the
  // query) and dropped if their mean term is more than preemptive_first_slack
  // (log units) below the model's best mean so far; then again, steadier, at
  // preemptive_second. Terms lie in [floor, 0] with a spread near 2.
  uint32_t preemptive_first = 0;
  float preemptive_first_slack = 0.0f;
  uint32_t preemptive_second = 0;
  float preemptive_second_slack = 0.0f;
};

// The hypothesis loop's likelihood (the paper's eqs. 4-7, DrawsParams).
LikelihoodParams make_likelihood_params(const StageParams& p, const Database& db);
// The final ranking's: the exact nearest-feature search, r to the model's
// surface patch (RefineParams::patch_radius_per_spacing of the basis
// spacing: a model feature stands for the surface of its basis voxel), and
// sigma_surface in eq. 5 (the sampling offset that sigma covers is gone).
// The floor stays the hypothesis loop's: an unexplained feature costs the
// same in both (one derived from sigma_surface ranked the fleet worse).
LikelihoodParams make_surface_params(const StageParams& p, const Database& db);

// The signed distance of x (model frame) from model feature m's tangent
// plane, along its normal: > 0 on the side the normal points to. Summed
// left to right, as the golden vectors were recorded (Eigen's dot pairs the
// last two first).
inline float offset_along_normal(const OrientedPoint& m, const Eigen::Vector3f& x) {
  const Eigen::Vector3f e = x - m.p;
  return e[0] * m.n[0] + e[1] * m.n[1] + e[2] * m.n[2];
}

// r^2 of eq. 5 for query feature x (model frame) and model feature f.
float residual2(const Database& db, uint32_t f, const Eigen::Vector3f& x, float point_to_point2,
                const LikelihoodParams& lp);

// Nearest model feature to x (model frame) within Delta_max whose normal n
// agrees within eta_max; feature < 0 when none. With lp.use_field, among
// the field voxel's slots (the features nearest the voxel's centre, one per
// surface orientation: O(slots)); otherwise exact, by searching the grid
// cells within Delta_max (blobs built without a field, or a Delta_max beyond
// the field's reach).
struct NearestFeature {
  int64_t feature = -1;
  float dist2 = 0.0f;
};
// The two searches, each out of line with only its own frame (the field's
// lookup runs once per verified feature).
NearestFeature nearest_in_field(const Database& db, const blob::ModelRecord& rec, const Eigen::Vector3f& x,
                                const Eigen::Vector3f& n, const LikelihoodParams& lp);
NearestFeature nearest_in_grid(const Database& db, const blob::ModelRecord& rec, const Eigen::Vector3f& x,
                               const Eigen::Vector3f& n, const LikelihoodParams& lp);
inline NearestFeature find_nearest_model_feature(const Database& db, const blob::ModelRecord& rec,
                                                 const Eigen::Vector3f& x, const Eigen::Vector3f& n,
                                                 const LikelihoodParams& lp) {
  return lp.use_field ? nearest_in_field(db, rec, x, n, lp) : nearest_in_grid(db, rec, x, n, lp);
}

// Query feature l in the model frame of `pose` (rt: its rotation transposed):
// position and normal. One expression for verification and refinement, so
// that both find the same nearest model feature for it: verification runs
// the frame-change kernel (kernels/nearest_select.hpp), which equals it bit
// for bit on every target (tests/core/test_nearest_kernels.cpp).
inline void query_in_model_frame(const QueryFeatures& query, uint32_t l, const Eigen::Matrix3f& rt,
                                 const Eigen::Vector3f& translation, Eigen::Vector3f* x, Eigen::Vector3f* n) {
  const Eigen::Vector3f qp(query.positions[3u * l], query.positions[3u * l + 1u],
                           query.positions[3u * l + 2u]);
  const Eigen::Vector3f qn(query.normals[3u * l], query.normals[3u * l + 1u], query.normals[3u * l + 2u]);
  *x = rt * (qp - translation);
  *n = rt * qn;
}

// The change of frame of `pose` for the nearest-feature kernels
// (kernels/nearest_select.hpp): verification's query_in_model_frame, bit
// for bit (tests/core/test_nearest_kernels.cpp).
kernels::FrameChange frame_change(const RigidPose& pose);

// What refine_pose pairs query feature l with: the nearest model feature
// within Delta, or kNoMatch.
constexpr int32_t kNoMatch = -1;
inline int32_t match_within_delta(const NearestFeature& near, const LikelihoodParams& lp) {
  return near.feature >= 0 && near.dist2 <= lp.delta2 ? near.feature : kNoMatch;
}

// A `to_beat` that every score beats: the full score is wanted.
constexpr float kNoScoreToBeat = -3.0e38f;

struct Verification {
  float log_likelihood = 0.0f;  // sum over query features, eq. 7
  uint32_t inliers = 0;         // features matched within Delta
  bool complete = false;        // false: stopped early, cannot beat `to_beat`
};

// Scores `pose` of `model` on query.verify_count features visited in an
// evenly spread order (all of them when verify_count == count). Stops early
// once even perfect remaining features (log p <= 0 each) could not lift the
// sum above `to_beat`, or once the first few dozen features say the pose is
// clearly worse than `reference` (a score on the same features; the model's
// own best, or the pose's source when a look-alike borrows it;
// kNoScoreToBeat: never). When `matches` is given, matches[l] receives
// each visited feature's match for refine_pose (kNoMatch beyond Delta).
Verification verify_pose(const Database& db, uint32_t model, const RigidPose& pose,
                         const QueryFeatures& query, const LikelihoodParams& lp, float to_beat,
                         float reference, int32_t* matches = nullptr);

}  // namespace spinhash
