#include "recognize/draws.hpp"

#include "recognize/box_distance.hpp"
#include "recognize/evidence_stop.hpp"
#include "recognize/hypotheses.hpp"
#include "recognize/model_groups.hpp"
#include "recognize/work_meter.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

// The draws go on past the budget (up to kTrialExtension times it) while
// they found fewer than min_hypotheses poses: among many look-alikes the W
// candidates of a query feature spread over them and few draws pair up in
// one model. A pose refused for its tilt (max_tilt_deg) was found all the
// same: the draws did pair up.
bool keep_drawing(const SearchContext& ctx) {
  const uint64_t drawn = ctx.stats.draws.trials, budget = trial_budget(ctx);
  return drawn < budget || (drawn < kTrialExtension * budget &&
                            ctx.stats.draws.poses_found() <
                                static_cast<uint64_t>(ctx.trial_scale) * ctx.params.draws.min_hypotheses);
}

// Look-alike doublets (lookalike_box_l1): each of feature k's candidates
// pairs with at most lookalike_pairs_per_candidate of feature l's candidates
// in look-alikes, the nearest in spin image that pass the cascade (the lists
// are sorted by L1): near-identical models hold near-identical features, so
// every further one would give nearly the same pose again. A draw verifies
// at most lookalike_pairs_per_draw look-alike poses: among identical copies
// every candidate has a look-alike partner.
bool lookalike_pair_allowed(const SearchContext& ctx, uint16_t a, uint16_t b, uint32_t pairs,
                            uint32_t draw_pairs) {
  const DrawsParams& d = ctx.params.draws;
  return pairs < d.lookalike_pairs_per_candidate && draw_pairs < d.lookalike_pairs_per_draw &&
         boxes_within(ctx.db.model(a), ctx.db.model(b), d.lookalike_box_l1);
}

// Every same-model candidate pair of features (k, l), and with spread
// candidates look-alike pairs; false once the budget is spent.
bool enumerate_pairs(SearchContext& ctx, uint32_t k, uint32_t l, const DoubletShape& shape,
                     const HypothesisCaps& caps) {
  const Candidate* ck = ctx.candidates_of(k);
  const Candidate* cl = ctx.candidates_of(l);
  const uint16_t* models = ctx.db.feature_models();
  const bool lookalikes = ctx.stats.candidates.spread && ctx.params.draws.lookalike_box_l1 > 0.0f;
  if (!lookalikes) {  // the paper's loop: same-model pairs only, through l's groups (model_groups.hpp)
    ModelGroups groups;
    group_by_model(cl, ctx.buf.candidate_count[l], models, &groups);
    for (uint32_t u = 0; u < ctx.buf.candidate_count[k]; ++u) {
      const uint16_t mu = models[ck[u].feature];
      for (uint32_t j = first_of_model(groups, mu); j < groups.count && groups.model[j] == mu; ++j)
        if (evaluate_pair(ctx, mu, k, l, shape, ck[u].feature, cl[groups.index[j]].feature, caps) ==
            PairOutcome::kBudgetSpent)
          return false;
    }
    return true;
  }
  uint32_t draw_pairs = 0;  // look-alike pairs of this draw through the cascade
  for (uint32_t u = 0; u < ctx.buf.candidate_count[k]; ++u) {
    const uint16_t mu = models[ck[u].feature];
    uint32_t pairs = 0;  // ... of candidate u
    for (uint32_t v = 0; v < ctx.buf.candidate_count[l]; ++v) {
      const uint16_t mv = models[cl[v].feature];
      const bool lookalike = mv != mu;
      if (lookalike && !lookalike_pair_allowed(ctx, mu, mv, pairs, draw_pairs)) continue;
      const PairOutcome o = evaluate_pair(ctx, mu, k, l, shape, ck[u].feature, cl[v].feature, caps);
      if (o == PairOutcome::kBudgetSpent) return false;
      if (lookalike && o == PairOutcome::kPassed) ++pairs, ++draw_pairs;
    }
  }
  return true;
}

// Batch RANSAC (section 9).
void draw_bran(SearchContext& ctx) {
  if (ctx.stats.candidates.salient_features < 2u) return;
  ctx.cumulative = ctx.buf.cumulative;
  const HypothesisCaps caps{ctx.params.draws.max_hypotheses, 0xFFFFFFFFu};
  while (keep_drawing(ctx)) {
    ++ctx.stats.draws.trials;
    uint32_t k = 0, l = 0;
    DoubletShape shape;
    if (!draw_stable_doublet(ctx, &k, &l, &shape)) continue;
    ++ctx.evidence.draws;
    if (!enumerate_pairs(ctx, k, l, shape, caps)) break;
    if (evidence_says_stop(ctx)) {
      ctx.stats.draws.stopped_on_evidence = true;
      break;
    }
  }
}

// Sequential RANSAC, the paper's SRAN baseline: every model in turn, with
// its own W nearest features per query feature (exhaustive per model, as a
// per-model matcher does) and its own trials. Cost grows linearly with the
// number of models.
void draw_sran(SearchContext& ctx) {
  const DrawsParams& d = ctx.params.draws;
  const HypothesisCaps caps{0xFFFFFFFFu, d.max_hypotheses};
  for (uint32_t model = 0; model < ctx.db.model_count(); ++model) {
    for (uint32_t l = 0; l < ctx.query.count; ++l) gather_model_candidates(ctx, model, l);
    draw_for_model(ctx, model, d.sran_trials, caps);  // a model's own cap ends its draws only
    // The global budget or the query's work cap spent: no further model is searched.
    if (ctx.stats.draws.pair_checks >= d.max_pair_checks || work_capped(ctx)) return;
  }
}

}  // namespace

uint64_t trial_budget(const SearchContext& ctx) {
  const uint64_t b = static_cast<uint64_t>(ctx.trial_scale) * ctx.params.draws.max_trials;
  return b < kMaxTrials ? b : kMaxTrials;
}

Status draws_stage(SearchContext& ctx) {
  if (ctx.mode == Mode::kBran) draw_bran(ctx);
  if (ctx.mode == Mode::kSran) draw_sran(ctx);
  return Status::kOk;
}

}  // namespace spinhash
