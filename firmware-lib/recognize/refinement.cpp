#include "recognize/refinement.hpp"

#include "match/refine_pose.hpp"
#include "recognize/final_lending.hpp"
#include "recognize/visible_surface.hpp"
#include "recognize/work_meter.hpp"
#include "spinhash/limits.hpp"
#include "util/top_n.hpp"

namespace spinhash {
namespace {

// Log units: a model not rescored ranks below every rescored one (any
// positive gap keeps that order).
constexpr float kBelowFinalised = 1.0f;

// Indices of the (up to) rescored_models best-scoring models, best first.
uint32_t leading_models(const SearchContext& ctx, uint32_t* out) {
  return top_n(
      ctx.db.model_count(), ctx.params.refine.rescored_models, out,
      [&](uint32_t m) { return has_hypothesis(ctx, m); },
      [&](uint32_t a, uint32_t b) { return scores_higher(ctx, a, b); });
}

// The pose turned end to end scores within turn_screen_slack per feature of
// `pose` on the hypothesis loop's features (its likelihood and feature
// subset): a near-symmetric vehicle; otherwise its two ends differ plainly
// and the turn is not worth a refinement.
bool turn_worth_refining(SearchContext& ctx, uint32_t model, const RigidPose& pose, const RigidPose& turned) {
  ctx.stats.refine.screens += 2u;
  const float as_found =
      verify_pose(ctx.db, model, pose, ctx.query, ctx.likelihood, kNoScoreToBeat, kNoScoreToBeat)
          .log_likelihood;
  const float threshold =
      as_found - ctx.params.refine.turn_screen_slack * static_cast<float>(ctx.query.verify_count);
  // Stopped once even perfect remaining features could not reach the
  // threshold: its partial sum is then below it, the same decision.
  const float turned_score =
      verify_pose(ctx.db, model, turned, ctx.query, ctx.likelihood, threshold, kNoScoreToBeat).log_likelihood;
  return turned_score >= threshold;
}

// Refines the model's pose, and its turn end to end when the turn is close
// (turn_worth_refining); keeps whichever scores higher. The turn is a
// refinement of its own: not begun once the query has spent its cap.
void refine_both_ways(SearchContext& ctx, uint32_t model, const QueryFeatures& all,
                      const LikelihoodParams& lp) {
  ModelBest& best = ctx.buf.best[model];
  const ModelBest as_found = best;
  refine_model(ctx, model, all, lp, false);  // the matches are another model's (all are rescored first)
  if (work_capped(ctx)) return;
  const RigidPose turned = turned_end_to_end(as_found.pose, ctx.db.model(model));
  if (!turn_worth_refining(ctx, model, as_found.pose, turned)) return;
  const ModelBest refined = best;
  best.pose = turned;
  rescore_model(ctx, model, all, lp);
  refine_model(ctx, model, all, lp, true);
  if (!(best.score > refined.score)) best = refined;
}

}  // namespace

void rescore_model(SearchContext& ctx, uint32_t model, const QueryFeatures& all, const LikelihoodParams& lp) {
  ModelBest& best = ctx.buf.best[model];
  ++ctx.stats.refine.rescores;
  Verification full =
      verify_pose(ctx.db, model, best.pose, all, lp, kNoScoreToBeat, kNoScoreToBeat, ctx.buf.matches);
  best.score = full.log_likelihood;
  best.inliers = full.inliers;
  best.final_score = true;
}

// A step from a pose that was just verified takes the matches that
// verification recorded in ctx.buf.matches, so it costs one search of the
// model, not two: every step after the first, and the first when
// `rescored`.
void refine_model(SearchContext& ctx, uint32_t model, const QueryFeatures& all, const LikelihoodParams& lp,
                  bool rescored) {
  ModelBest& best = ctx.buf.best[model];
  const RefineParams& p = ctx.params.refine;
  bool have_matches = rescored;
  for (uint32_t it = 0; it < p.refine_iterations; ++it) {
    RigidPose pose = best.pose;
    if (!refine_pose(ctx.db, model, all, lp, &pose, have_matches ? ctx.buf.matches : nullptr,
                     p.damping_per_match))
      return;
    // On a lower score the loop ends: the matches are then the rejected pose's, and unused.
    Verification v =
        verify_pose(ctx.db, model, pose, all, lp, kNoScoreToBeat, kNoScoreToBeat, ctx.buf.matches);
    have_matches = true;
    ++ctx.stats.refine.refinements;
    if (!(v.log_likelihood > best.score)) return;
    best.score = v.log_likelihood;
    best.pose = pose;
    best.inliers = v.inliers;
  }
}

bool final_first(const SearchContext& ctx, uint32_t* first) {
  bool found = false;
  for (uint32_t m = 0; m < ctx.db.model_count(); ++m)
    if (ctx.buf.best[m].final_score && (!found || scores_higher(ctx, m, *first))) *first = m, found = true;
  return found;
}

Status refine_stage(SearchContext& ctx) {
  if (ctx.mode == Mode::kSind) return Status::kOk;  // votes are no likelihoods
  const RefineParams& p = ctx.params.refine;
  const bool refine = p.refine_poses;
  uint32_t models[kMaxRescoredModels];
  const uint32_t leaders = leading_models(ctx, models);
  QueryFeatures all = ctx.query;
  all.verify_count = all.count;
  const LikelihoodParams exact = make_surface_params(ctx.params, ctx.db);
  float leading = kNoScoreToBeat;
  // Once the query has spent its cap, no further leader is rescored: the
  // first n are finalised, the rest keep their subset scores, below them,
  // as the models outside the leading set do.
  uint32_t n = 0;  // the leaders rescored
  for (; n < leaders && !work_capped(ctx); ++n) {
    rescore_model(ctx, models[n], all, exact);
    leading = ctx.buf.best[models[n]].score > leading ? ctx.buf.best[models[n]].score : leading;
  }
  // A rescored model refine_window per feature below the best is not
  // refined: the least squares cost most of the stage, and a pose this much
  // worse is a wrong model, not a few centimetres off.
  const float refine_from = leading - p.refine_window * static_cast<float>(all.count);
  index_query_features(ctx);  // BRAN's upward surface; every mode's coverage
  float lowest_final = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    ModelBest& b = ctx.buf.best[models[i]];
    // Capped, a rescored leader is finalised unrefined (its upward surface
    // charged like the others', so the finalised scores stay comparable).
    if (refine && b.score >= refine_from && !work_capped(ctx)) refine_both_ways(ctx, models[i], all, exact);
    if (ctx.mode == Mode::kBran) b.score += upward_surface(ctx, models[i], b.pose).log_likelihood;
    lowest_final = i == 0 || b.score < lowest_final ? b.score : lowest_final;
  }
  if (ctx.mode == Mode::kBran) lend_final_pose(ctx, all, exact, refine);
  // Subset scores of the others, scaled to all features and kept below the
  // finalised ones (which alone were checked for their visible surface).
  const float scale = static_cast<float>(all.count) / static_cast<float>(ctx.query.verify_count);
  for (uint32_t m = 0; m < ctx.db.model_count(); ++m) {
    ModelBest& b = ctx.buf.best[m];
    if (b.has_score && b.hypotheses > 0 && !b.final_score) {
      b.score *= scale;
      if (n > 0 && b.score >= lowest_final) b.score = lowest_final - kBelowFinalised;
      b.inliers = static_cast<uint32_t>(static_cast<float>(b.inliers) * scale);
    }
  }
  return Status::kOk;
}

}  // namespace spinhash
