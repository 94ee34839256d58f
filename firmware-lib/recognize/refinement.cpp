// After the hypothesis loop, which scores poses on a subset of the query
// features (through the blob's nearest-feature field when it has one): the
// leading models' best poses are rescored on every feature with the exact
// nearest-feature search and the surface residual (make_surface_params:
// each query feature's distance to the model's surface along the nearest
// model feature's normal, with sigma_surface; the paper's distance to the
// feature itself carries the basis voxels' sampling offset, up to 0.2 m,
// which blurs the centimetres that separate look-alikes); those within
// kRefineWindow of the best are (optionally) refined point to plane
// (match/refine_pose.hpp), from the pose as found and, when it is close on
// the hypothesis loop's features, from the pose turned end to end (a
// near-symmetric vehicle's hypothesis may come the wrong way round: 49 of
// the fleet's 827 right answers did), keeping the refined pose with the
// higher likelihood; BRAN then charges each for the upward surface the scan does not
// show (visible_surface.cpp) and lends the first model's refined pose to
// its look-alikes (final_lending.cpp); every other model's subset score is
// extrapolated to all features, below the rescored ones. Bounded:
// kRefinedModels models x (2 + 2 kRefineIterations) full verifications,
// and the lending's own bound.
#include "match/refine_pose.hpp"
#include "recognize/search_context.hpp"
#include "util/top_n.hpp"

namespace spinhash {
namespace {

constexpr uint32_t kRefinedModels = 8;
constexpr uint32_t kRefineIterations = 3;
// Log units per query feature: a rescored model this far below the best is
// not refined (the refinement's least squares cost most of the finalisation,
// and a pose this much worse is a wrong model, not a few centimetres off).
constexpr float kRefineWindow = 0.5f;
constexpr float kBelowFinalised = 1.0f;  // log units: a model not rescored ranks below every rescored one
// Log units per verified feature: the pose turned end to end is refined
// too when, on the hypothesis loop's features, it scores at most this much
// below the pose as found (a near-symmetric vehicle); otherwise the
// vehicle's two ends differ plainly and the turn is not worth a refinement.
constexpr float kTurnScreenSlack = 0.3f;
// Indices of the (up to) kRefinedModels best-scoring models, best first.
uint32_t leading_models(const SearchContext& ctx, uint32_t* out) {
  return top_n(
      ctx.db.model_count(), kRefinedModels, out, [&](uint32_t m) { return has_hypothesis(ctx, m); },
      [&](uint32_t a, uint32_t b) { return scores_higher(ctx, a, b); });
}

// The pose turned end to end scores within kTurnScreenSlack of `pose` on
// the hypothesis loop's features (its likelihood and feature subset).
bool turn_worth_refining(SearchContext& ctx, uint32_t model, const RigidPose& pose, const RigidPose& turned) {
  const float as_found =
      verify_pose(ctx.db, model, pose, ctx.query, ctx.likelihood, kNoScoreToBeat, kNoScoreToBeat)
          .log_likelihood;
  const float threshold = as_found - kTurnScreenSlack * static_cast<float>(ctx.query.verify_count);
  // Stopped once even perfect remaining features could not reach the
  // threshold: its partial sum is then below it, the same decision.
  const float turned_score =
      verify_pose(ctx.db, model, turned, ctx.query, ctx.likelihood, threshold, kNoScoreToBeat).log_likelihood;
  return turned_score >= threshold;
}

// Refines the model's pose, and its turn end to end when the turn is close
// (turn_worth_refining); keeps whichever scores higher.
void refine_both_ways(SearchContext& ctx, uint32_t model, const QueryFeatures& all,
                      const LikelihoodParams& lp) {
  ModelBest& best = ctx.buf.best[model];
  const ModelBest as_found = best;
  refine_model(ctx, model, all, lp, false);  // the matches are another model's (all are rescored first)
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
  bool have_matches = rescored;
  for (uint32_t it = 0; it < kRefineIterations; ++it) {
    RigidPose pose = best.pose;
    if (!refine_pose(ctx.db, model, all, lp, &pose, have_matches ? ctx.buf.matches : nullptr)) return;
    // On a lower score the loop ends: the matches are then the rejected pose's, and unused.
    Verification v =
        verify_pose(ctx.db, model, pose, all, lp, kNoScoreToBeat, kNoScoreToBeat, ctx.buf.matches);
    have_matches = true;
    ++ctx.stats.refinements;
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

void finalise_scores(SearchContext& ctx, bool refine) {
  uint32_t models[kRefinedModels];
  const uint32_t n = leading_models(ctx, models);
  QueryFeatures all = ctx.query;
  all.verify_count = all.count;
  const LikelihoodParams exact = make_surface_params(ctx.cfg, ctx.db);
  float leading = kNoScoreToBeat;
  for (uint32_t i = 0; i < n; ++i) {
    rescore_model(ctx, models[i], all, exact);
    leading = ctx.buf.best[models[i]].score > leading ? ctx.buf.best[models[i]].score : leading;
  }
  const float refine_from = leading - kRefineWindow * static_cast<float>(all.count);
  index_query_features(ctx);  // BRAN's upward surface; every mode's coverage
  float lowest_final = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    ModelBest& b = ctx.buf.best[models[i]];
    if (refine && b.score >= refine_from) refine_both_ways(ctx, models[i], all, exact);
    if (ctx.cfg.mode == Mode::kBran) b.score += upward_surface(ctx, models[i], b.pose).log_likelihood;
    lowest_final = i == 0 || b.score < lowest_final ? b.score : lowest_final;
  }
  if (ctx.cfg.mode == Mode::kBran) lend_final_pose(ctx, all, exact, refine);
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
}

}  // namespace spinhash
