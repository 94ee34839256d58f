#include "match/likelihood.hpp"

#include <cmath>

#include "kernels/l1_select.hpp"
#include "kernels/nearest_select.hpp"
#include "util/angle_math.hpp"

namespace spinhash {
namespace {

constexpr float kMaxNormalisedL1 = 2.0f;  // L1 between two sum-1 histograms

}  // namespace

namespace {

// Squared distance from coordinate v to cell c's extent [c, c + 1) * cell (0 inside).
inline float axis_gap2(float v, int32_t c, float cell) {
  float lo = static_cast<float>(c) * cell, hi = lo + cell;
  float g = v < lo ? lo - v : (v > hi ? v - hi : 0.0f);
  return g * g;
}

// Model feature f against x (x[0..2], model frame): becomes best if nearer with an agreeing normal.
inline void consider_feature(const Database& db, uint32_t f, const float* x, const float* n,
                             float cos_eta_max, NearestFeature* best) {
  const float* p = db.positions() + 3u * f;
  float ex = p[0] - x[0], ey = p[1] - x[1], ez = p[2] - x[2];
  float d2 = ex * ex + ey * ey + ez * ez;
  if (d2 >= best->dist2) return;
  const int16_t* m = db.normals() + 3u * f;
  float dot =
      (static_cast<float>(m[0]) * n[0] + static_cast<float>(m[1]) * n[1] + static_cast<float>(m[2]) * n[2]) *
      (1.0f / 32767.0f);
  if (dot < cos_eta_max) return;
  best->dist2 = d2;
  best->feature = f;
}

// Features of one grid cell against x: updates best (nearest within best.dist2 with agreeing normal).
void scan_cell(const Database& db, const blob::ModelRecord& rec, uint32_t cell_index,
               const Eigen::Vector3f& x, const Eigen::Vector3f& n, float cos_eta_max, NearestFeature* best) {
  const uint32_t* offsets = db.grid_offsets() + rec.grid_offset_base;
  const uint32_t end = rec.first_feature + offsets[cell_index + 1u];
  for (uint32_t f = rec.first_feature + offsets[cell_index]; f < end; ++f)
    consider_feature(db, f, x.data(), n.data(), cos_eta_max, best);
}

// The model's field as the kernels' box; set up once per verified pose.
kernels::FieldBox field_box(const Database& db, const blob::ModelRecord& rec) {
  const blob::Params& p = db.params();
  kernels::FieldBox b;
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = rec.grid_origin[a] - p.field_reach;
    b.dims[a] = static_cast<float>(rec.field_dims[a]);
  }
  b.lo[3] = 0.0f;
  b.dims[3] = 1.0f;
  b.cell = p.field_cell;
  return b;
}

// With a SIMD kernel the field lookup is short and verify_pose inlines it;
// with the reference (bare metal, armhf) one out-of-line copy keeps the
// code small.
#if defined(SPINHASH_KERNELS_NEAREST_SIMD)
#define SPINHASH_FIELD_LOOKUP inline
#else
#define SPINHASH_FIELD_LOOKUP __attribute__((noinline))
#endif

// The slots of the field voxel holding x (blob_format.hpp): O(field_slots).
// x and n: four floats each (kernels/nearest_select.hpp).
SPINHASH_FIELD_LOOKUP NearestFeature nearest_in_box(const Database& db, const blob::ModelRecord& rec,
                                                    const kernels::FieldBox& box, const float* x,
                                                    const float* n, const LikelihoodParams& lp) {
  NearestFeature best;
  best.dist2 = lp.delta_max2;
  uint32_t v[4];
  // Outside the field (also inf/NaN from an extreme pose): farther than field_reach from every feature.
  if (!kernels::field_voxel(box, x, v)) return best;
  const uint32_t slots = db.params().field_slots;
  const uint16_t* slot =
      db.nearest_field() + rec.field_base +
      static_cast<size_t>(slots) * (v[0] + rec.field_dims[0] * (v[1] + rec.field_dims[1] * v[2]));
  for (uint32_t s = 0; s < slots && slot[s] != blob::kNoFieldFeature; ++s)
    consider_feature(db, rec.first_feature + slot[s], x, n, lp.cos_eta_max, &best);
  return best;
}

}  // namespace

NearestFeature nearest_in_field(const Database& db, const blob::ModelRecord& rec, const Eigen::Vector3f& x,
                                const Eigen::Vector3f& n, const LikelihoodParams& lp) {
  alignas(16) const float x4[4] = {x[0], x[1], x[2], 0.0f};
  alignas(16) const float n4[4] = {n[0], n[1], n[2], 0.0f};
  return nearest_in_box(db, rec, field_box(db, rec), x4, n4, lp);
}

NearestFeature nearest_in_grid(const Database& db, const blob::ModelRecord& rec, const Eigen::Vector3f& x,
                               const Eigen::Vector3f& n, const LikelihoodParams& lp) {
  NearestFeature best;
  best.dist2 = lp.delta_max2;
  const float cell = db.params().grid_cell;
  const int32_t r = static_cast<int32_t>(lp.reach);
  int32_t centre[3], lo[3], hi[3];
  float gap[3][2 * kMaxGridReach + 1];  // squared distance from x to each cell slab, per axis
  for (int a = 0; a < 3; ++a) {
    const float local = x[a] - rec.grid_origin[a];
    const int32_t dim = static_cast<int32_t>(rec.grid_dims[a]);
    const float f = std::floor(local / cell);
    // Beyond the grid by more than the reach (also inf/NaN from an extreme pose): no match.
    if (!(f > static_cast<float>(-r - 1) && f < static_cast<float>(dim + r))) return best;
    centre[a] = static_cast<int32_t>(f);
    lo[a] = centre[a] - r < 0 ? 0 : centre[a] - r;
    hi[a] = centre[a] + r >= dim ? dim - 1 : centre[a] + r;
    if (lo[a] > hi[a]) return best;  // x is farther than Delta_max from the model's grid
    for (int32_t k = lo[a]; k <= hi[a]; ++k) gap[a][k - lo[a]] = axis_gap2(local, k, cell);
  }
  const int32_t dx = static_cast<int32_t>(rec.grid_dims[0]), dy = static_cast<int32_t>(rec.grid_dims[1]);
  auto index = [&](int32_t i, int32_t j, int32_t k) { return static_cast<uint32_t>(i + dx * (j + dy * k)); };
  const bool centre_inside = centre[0] >= lo[0] && centre[0] <= hi[0] && centre[1] >= lo[1] &&
                             centre[1] <= hi[1] && centre[2] >= lo[2] && centre[2] <= hi[2];
  // The cell holding x first: a near match there lets most neighbours be skipped.
  if (centre_inside) scan_cell(db, rec, index(centre[0], centre[1], centre[2]), x, n, lp.cos_eta_max, &best);
  for (int32_t k = lo[2]; k <= hi[2]; ++k) {
    const float gz = gap[2][k - lo[2]];
    if (gz >= best.dist2) continue;
    for (int32_t j = lo[1]; j <= hi[1]; ++j) {
      const float gyz = gz + gap[1][j - lo[1]];
      if (gyz >= best.dist2) continue;
      for (int32_t i = lo[0]; i <= hi[0]; ++i) {
        if (gyz + gap[0][i - lo[0]] >= best.dist2) continue;  // the whole cell is farther
        if (centre_inside && i == centre[0] && j == centre[1] && k == centre[2]) continue;
        scan_cell(db, rec, index(i, j, k), x, n, lp.cos_eta_max, &best);
      }
    }
  }
  return best;
}

namespace {

// Per-feature log-likelihood of an unexplained feature: a match at Delta
// with the most dissimilar spin image.
float floor_term(const LikelihoodParams& lp, const DrawsParams& d) {
  return -lp.delta2 * lp.inv_two_sigma2 - kMaxNormalisedL1 / d.spin_lambda;
}

}  // namespace

LikelihoodParams make_likelihood_params(const StageParams& p, const Database& db) {
  const DrawsParams& d = p.draws;
  LikelihoodParams lp;
  lp.inv_two_sigma2 = 1.0f / (2.0f * d.sigma * d.sigma);
  lp.delta2 = d.delta * d.delta;
  lp.delta_max2 = d.delta_max * d.delta_max;
  lp.cos_eta_max = std::cos(deg_to_rad(d.eta_max_deg));
  lp.spin_weight = 1.0f / (d.spin_lambda * db.params().spin_quant_scale);
  lp.floor = floor_term(lp, d);
  const float reach = std::ceil(d.delta_max / db.params().grid_cell);
  lp.reach = reach < static_cast<float>(kMaxGridReach) ? static_cast<uint32_t>(reach) : kMaxGridReach;
  lp.use_field = db.has_nearest_field() && d.delta_max <= db.params().field_reach;
  lp.preemptive_first = d.preemptive_first;
  lp.preemptive_first_slack = d.preemptive_first_slack;
  lp.preemptive_second = d.preemptive_second;
  lp.preemptive_second_slack = d.preemptive_second_slack;
  return lp;
}

LikelihoodParams make_surface_params(const StageParams& p, const Database& db) {
  LikelihoodParams lp = make_likelihood_params(p, db);
  lp.use_field = false;  // the field's voxel-centre answers blur centimetres
  lp.inv_two_sigma2 = 1.0f / (2.0f * p.refine.sigma_surface * p.refine.sigma_surface);
  lp.surface_patch_radius = p.refine.patch_radius_per_spacing * db.params().basis_spacing;
  return lp;
}

kernels::FrameChange frame_change(const RigidPose& pose) {
  kernels::FrameChange f;
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) f.col[k][i] = pose.rotation(k, i);  // R^T(i, k)
    f.col[k][3] = 0.0f;
    f.t[k] = pose.translation[k];
  }
  f.t[3] = 0.0f;
  return f;
}

float residual2(const Database& db, uint32_t f, const Eigen::Vector3f& x, float point_to_point2,
                const LikelihoodParams& lp) {
  if (lp.surface_patch_radius < 0.0f) return point_to_point2;
  const float along_normal = offset_along_normal(model_feature_point(db, f), x);
  const float tangential2 = point_to_point2 - along_normal * along_normal;
  const float tangential = tangential2 > 0.0f ? std::sqrt(tangential2) : 0.0f;
  const float beyond = tangential > lp.surface_patch_radius ? tangential - lp.surface_patch_radius : 0.0f;
  return along_normal * along_normal + beyond * beyond;
}

namespace {

// The exact search for x and n given as four floats each.
NearestFeature nearest_in_grid_of(const Database& db, const blob::ModelRecord& rec, const float* x,
                                  const float* n, const LikelihoodParams& lp) {
  return nearest_in_grid(db, rec, Eigen::Vector3f(x[0], x[1], x[2]), Eigen::Vector3f(n[0], n[1], n[2]), lp);
}

// A stride coprime with n visits 0..n-1 once each, spread over the query.
uint32_t spread_stride(uint32_t n) {
  const uint32_t kCandidates[] = {7919u, 104729u, 1299709u, 15485863u};  // primes
  for (uint32_t p : kCandidates)
    if (n % p != 0u) return p % n;
  return 1u;
}

}  // namespace

Verification verify_pose(const Database& db, uint32_t model, const RigidPose& pose,
                         const QueryFeatures& query, const LikelihoodParams& lp, float to_beat,
                         float reference, int32_t* matches) {
  Verification v;
  const blob::ModelRecord& rec = db.model(model);
  const kernels::FrameChange frame = frame_change(pose);
  const kernels::FieldBox box = field_box(db, rec);
  alignas(16) float x[4] = {}, nm[4] = {};  // lanes 0-2: the feature in the model frame
  const uint32_t n = query.count;
  const uint32_t used = query.verify_count < n ? query.verify_count : n;
  const uint32_t stride = n > 1u ? spread_stride(n) : 1u;
  const bool preemptive = reference > kNoScoreToBeat;
  const float best_mean = reference / static_cast<float>(used > 0u ? used : 1u);
  uint32_t l = 0;
  // l + stride < 2n: one subtraction is the modulo (stride < n).
  for (uint32_t i = 0; i < used; ++i, l = l + stride >= n ? l + stride - n : l + stride) {
    if (v.log_likelihood < to_beat) return v;  // remaining terms are <= 0
    if (preemptive && ((i == lp.preemptive_first &&
                        v.log_likelihood / static_cast<float>(i) < best_mean - lp.preemptive_first_slack) ||
                       (i == lp.preemptive_second &&
                        v.log_likelihood / static_cast<float>(i) < best_mean - lp.preemptive_second_slack)))
      return v;
    kernels::to_model_frame(frame, query.positions + 3u * l, query.normals + 3u * l, x, nm);
    NearestFeature near =
        lp.use_field ? nearest_in_box(db, rec, box, x, nm, lp) : nearest_in_grid_of(db, rec, x, nm, lp);
    if (matches != nullptr) matches[l] = match_within_delta(near, lp);
    if (near.feature < 0) {
      v.log_likelihood += lp.floor;
      continue;
    }
    // The hypothesis loop's r is the paper's (no call for it).
    float r2 = lp.surface_patch_radius < 0.0f ? near.dist2
                                              : residual2(db, static_cast<uint32_t>(near.feature),
                                                          Eigen::Vector3f(x[0], x[1], x[2]), near.dist2, lp);
    r2 = r2 < lp.delta2 ? r2 : lp.delta2;
    uint32_t l1 = kernels::l1_distance(query.spins + static_cast<size_t>(l) * query.dims,
                                       db.spin(static_cast<uint32_t>(near.feature)), query.dims);
    float term = -r2 * lp.inv_two_sigma2 - static_cast<float>(l1) * lp.spin_weight;
    v.log_likelihood += term > lp.floor ? term : lp.floor;
    v.inliers += near.dist2 <= lp.delta2 ? 1u : 0u;
  }
  v.complete = true;
  return v;
}

}  // namespace spinhash
