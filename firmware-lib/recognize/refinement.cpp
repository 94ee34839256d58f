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
// show (visible_surface.cpp); every other model's subset score is
// extrapolated to all features, below the rescored ones. When the
// candidates were spread over look-alikes, the first model's refined pose
// is lent to its nearest look-alikes, which are refined and scored alike
// (lend_final_pose). Bounded: kRefinedModels models x (2 + 2
// kRefineIterations) full verifications, and kFinalLendRounds x
// kFinalLookalikes x (1 + kRefineIterations) more on spread candidates.
#include "match/refine_pose.hpp"
#include "recognize/box_distance.hpp"
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
// Look-alikes, by bounding box, that the first model's refined pose is lent
// to at the end when the candidates were spread (capped by transfer_models).
// Among 143 near-identical members of a family the draws score a few dozen;
// the scanned model was then often a near neighbour of the wrong first one,
// whose pose fits it within centimetres, but never refined.
constexpr uint32_t kFinalLookalikes = 16;
// A lent pose may put one of those look-alikes first: its own look-alikes
// then get the same chance, once.
constexpr uint32_t kFinalLendRounds = 2;

// Indices of the (up to) kRefinedModels best-scoring models, best first.
uint32_t leading_models(const SearchContext& ctx, uint32_t* out) {
  return top_n(
      ctx.db.model_count(), kRefinedModels, out, [&](uint32_t m) { return has_hypothesis(ctx, m); },
      [&](uint32_t a, uint32_t b) { return scores_higher(ctx, a, b); });
}

// The model's best pose scored on every query feature (its matches kept in
// ctx.buf.matches).
void rescore(SearchContext& ctx, uint32_t model, const QueryFeatures& all, const LikelihoodParams& lp) {
  ModelBest& best = ctx.buf.best[model];
  Verification full =
      verify_pose(ctx.db, model, best.pose, all, lp, kNoScoreToBeat, kNoScoreToBeat, ctx.buf.matches);
  best.score = full.log_likelihood;
  best.inliers = full.inliers;
  best.final_score = true;
}

// Least-squares steps while they raise the score. A step from a pose that
// was just verified takes the matches that verification recorded in
// ctx.buf.matches, so it costs one search of the model, not two: every
// step after the first, and the first when `rescored` (ctx.buf.matches
// still holds the rescoring of best.pose).
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

// The pose turned end to end scores within kTurnScreenSlack of `pose` on
// the hypothesis loop's features (its likelihood and feature subset).
bool turn_worth_refining(SearchContext& ctx, uint32_t model, const RigidPose& pose, const RigidPose& turned) {
  const float as_found =
      verify_pose(ctx.db, model, pose, ctx.query, ctx.likelihood, kNoScoreToBeat, kNoScoreToBeat)
          .log_likelihood;
  const float turned_score =
      verify_pose(ctx.db, model, turned, ctx.query, ctx.likelihood, kNoScoreToBeat, kNoScoreToBeat)
          .log_likelihood;
  return turned_score >= as_found - kTurnScreenSlack * static_cast<float>(ctx.query.verify_count);
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
  rescore(ctx, model, all, lp);
  refine_model(ctx, model, all, lp, true);
  if (!(best.score > refined.score)) best = refined;
}

// The model with the highest final score; false when none has one.
bool final_first(const SearchContext& ctx, uint32_t* first) {
  bool found = false;
  for (uint32_t m = 0; m < ctx.db.model_count(); ++m)
    if (ctx.buf.best[m].final_score && (!found || scores_higher(ctx, m, *first))) *first = m, found = true;
  return found;
}

// Lends `source`'s final pose to its nearest look-alikes not yet finalised,
// rescoring and refining each there as the leading models were.
void lend_final_pose(SearchContext& ctx, uint32_t source, const QueryFeatures& all,
                     const LikelihoodParams& exact, bool refine) {
  const uint32_t wanted =
      ctx.cfg.transfer_models < kFinalLookalikes ? ctx.cfg.transfer_models : kFinalLookalikes;
  uint32_t targets[kFinalLookalikes];
  const uint32_t n = nearest_by_box(ctx.db, source, wanted, targets,
                                    [&](uint32_t m) { return !ctx.buf.best[m].final_score; });
  for (uint32_t t = 0; t < n; ++t) {
    ModelBest& b = ctx.buf.best[targets[t]];
    b.pose = ctx.buf.best[source].pose;
    b.has_score = true;
    ++b.hypotheses;
    ++ctx.stats.transferred;
    rescore(ctx, targets[t], all, exact);
    if (refine) refine_model(ctx, targets[t], all, exact, true);
    b.score += upward_surface_log_likelihood(ctx, targets[t], b.pose);
  }
}

// Candidates spread over look-alikes (BRAN): the first model's pose lent to
// its nearest look-alikes, and again from a look-alike that comes first.
void lend_to_lookalikes(SearchContext& ctx, const QueryFeatures& all, const LikelihoodParams& exact,
                        bool refine) {
  if (!ctx.stats.candidates_spread) return;
  uint32_t lent_from = ctx.db.model_count();  // none yet
  for (uint32_t round = 0; round < kFinalLendRounds; ++round) {
    uint32_t first = 0;
    if (!final_first(ctx, &first) || first == lent_from) return;
    lend_final_pose(ctx, first, all, exact, refine);
    lent_from = first;
  }
}

}  // namespace

void finalise_scores(SearchContext& ctx, bool refine) {
  uint32_t models[kRefinedModels];
  const uint32_t n = leading_models(ctx, models);
  QueryFeatures all = ctx.query;
  all.verify_count = all.count;
  const LikelihoodParams exact = make_surface_params(ctx.cfg, ctx.db);
  float leading = kNoScoreToBeat;
  for (uint32_t i = 0; i < n; ++i) {
    rescore(ctx, models[i], all, exact);
    leading = ctx.buf.best[models[i]].score > leading ? ctx.buf.best[models[i]].score : leading;
  }
  const float refine_from = leading - kRefineWindow * static_cast<float>(all.count);
  if (ctx.cfg.mode == Mode::kBran) index_query_features(ctx);
  float lowest_final = 0.0f;
  for (uint32_t i = 0; i < n; ++i) {
    ModelBest& b = ctx.buf.best[models[i]];
    if (refine && b.score >= refine_from) refine_both_ways(ctx, models[i], all, exact);
    if (ctx.cfg.mode == Mode::kBran) b.score += upward_surface_log_likelihood(ctx, models[i], b.pose);
    lowest_final = i == 0 || b.score < lowest_final ? b.score : lowest_final;
  }
  lend_to_lookalikes(ctx, all, exact, refine);
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
