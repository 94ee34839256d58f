#include "recognize/hypotheses.hpp"

#include "recognize/work_meter.hpp"

#include "match/likelihood.hpp"
#include "match/pose_from_doublet.hpp"
#include "recognize/evidence_stop.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

uint32_t draw_index(SearchContext& ctx) {
  const uint32_t n = ctx.query.count;
  if (ctx.cumulative == nullptr) return ctx.rng.below(n);
  const float total = ctx.cumulative[n - 1u];
  const float u = ctx.rng.uniform() * total;
  uint32_t lo = 0, hi = n - 1u;  // first index whose running sum exceeds u
  while (lo < hi) {              // log2(n) steps
    uint32_t mid = lo + (hi - lo) / 2u;
    if (ctx.cumulative[mid] > u)
      hi = mid;
    else
      lo = mid + 1u;
  }
  return lo;
}

}  // namespace

bool draw_stable_doublet(SearchContext& ctx, uint32_t* k, uint32_t* l, DoubletShape* shape) {
  for (uint32_t attempt = 0; attempt < kMaxStabilityRetries; ++attempt) {
    uint32_t a = draw_index(ctx), b = draw_index(ctx);
    if (a == b) continue;
    if (!doublet_shape(ctx.query_point(a), ctx.query_point(b), shape)) continue;
    if (!is_stable(*shape, ctx.d_min, ctx.theta_min)) continue;
    *k = a;
    *l = b;
    return true;
  }
  return false;
}

void consider_pose(SearchContext& ctx, uint32_t model, const RigidPose& pose, float source_score) {
  ModelBest& best = ctx.buf.best[model];
  ++best.hypotheses;
  const float to_beat = best.has_score ? best.score : kNoScoreToBeat;
  const float reference = best.has_score ? best.score : source_score;
  Verification v = verify_pose(ctx.db, model, pose, ctx.query, ctx.likelihood, to_beat, reference);
  if (v.complete && (!best.has_score || v.log_likelihood > best.score)) {
    best.score = v.log_likelihood;
    best.pose = pose;
    best.inliers = v.inliers;
    best.has_score = true;
    note_leader(ctx, model);
  }
}

uint32_t gather_model_candidates(SearchContext& ctx, uint32_t model, uint32_t l) {
  const uint32_t n =
      search_model_exhaustive(ctx.db, model, ctx.query.spins + static_cast<size_t>(l) * ctx.query.dims,
                              ctx.params.candidates.top_w_sran, ctx.candidates_of(l));
  ctx.buf.candidate_count[l] = n;
  ctx.stats.candidates.kept += n;
  return n;
}

bool draw_for_model(SearchContext& ctx, uint32_t model, uint32_t trials, const HypothesisCaps& caps) {
  for (uint32_t trial = 0; trial < trials; ++trial) {
    ++ctx.stats.draws.trials;
    uint32_t k = 0, l = 0;
    DoubletShape shape;
    if (!draw_stable_doublet(ctx, &k, &l, &shape)) continue;
    const Candidate* ck = ctx.candidates_of(k);
    const Candidate* cl = ctx.candidates_of(l);
    for (uint32_t u = 0; u < ctx.buf.candidate_count[k]; ++u)
      for (uint32_t v = 0; v < ctx.buf.candidate_count[l]; ++v)
        if (evaluate_pair(ctx, model, k, l, shape, ck[u].feature, cl[v].feature, caps) ==
            PairOutcome::kBudgetSpent)
          return false;
  }
  return true;
}

// Out of line: one copy for its callers here and in the draws keeps the
// code small.
__attribute__((noinline)) PairOutcome evaluate_pair(SearchContext& ctx, uint32_t model, uint32_t k,
                                                    uint32_t l, const DoubletShape& shape, uint32_t fu,
                                                    uint32_t fv, const HypothesisCaps& caps) {
  DrawsStats& st = ctx.stats.draws;
  // The cap's sum inline (work_capped calls it): this runs for every pair.
  if (st.pair_checks >= ctx.params.draws.max_pair_checks ||
      ctx.work_before + pass_work(ctx.stats, ctx.params) >= ctx.work_cap) {
    st.budget_exhausted = true;
    return PairOutcome::kBudgetSpent;
  }
  ++st.pair_checks;
  if (fu == fv) return PairOutcome::kRejected;
  // The separation needs no normals: a pair it rejects never decodes them.
  const Eigen::Vector3f pu = model_feature_position(ctx.db, fu), pv = model_feature_position(ctx.db, fv);
  const Eigen::Vector3f delta = pv - pu;
  const float d = delta.norm();
  if (!separation_agrees(shape, d, ctx.tolerance)) return PairOutcome::kRejected;
  const OrientedPoint mu{pu, model_feature_normal(ctx.db, fu)}, mv{pv, model_feature_normal(ctx.db, fv)};
  if (check_doublet_normals(shape, mu.n, mv.n, delta, d, ctx.tolerance) != CascadeStage::kPass)
    return PairOutcome::kRejected;
  ++st.doublets_passed;
  RigidPose pose;
  if (!pose_from_doublet(ctx.query_point(k), ctx.query_point(l), mu, mv, &pose,
                         ctx.params.draws.normal_lever))
    return PairOutcome::kPassed;
  // The total budget counts the poses found, tilted ones too: a sphere
  // pairs with any patch, and counting only the verified poses took the
  // worst cases' draws (docs/budgets.md) to 1.6-2x their instructions.
  if (pose.rotation(2, 2) < ctx.min_up_z) {  // the model's z under the pose: it would not stand
    ++st.poses_tilted;
    if (st.poses_found() < caps.total) return PairOutcome::kRejected;
    st.budget_exhausted = true;
    return PairOutcome::kBudgetSpent;
  }
  ++st.hypotheses;
  consider_pose(ctx, model, pose);
  if (st.poses_found() >= caps.total || ctx.buf.best[model].hypotheses >= caps.per_model) {
    st.budget_exhausted = true;
    return PairOutcome::kBudgetSpent;
  }
  return PairOutcome::kPassed;
}

}  // namespace spinhash
