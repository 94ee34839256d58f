// Batch RANSAC (section 9): candidates of every query feature from the joint
// index, saliency-weighted doublet draws, and for each draw every candidate
// pair of one model (the exhaustive W_k x W_l option) through the cascade,
// and when the candidates are spread over look-alikes also pairs of two
// look-alikes (not in the paper), until the evidence says the leader is
// found (evidence_stop.cpp) or the work budget is spent (max_trials draws,
// more while min_hypotheses is not met); when the candidates are spread
// over look-alikes, or the draws had to be extended, the leading models get
// a focused search of their own.
#include <cmath>

#include "recognize/box_distance.hpp"
#include "recognize/model_groups.hpp"
#include "recognize/search_context.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

// The draws' budget: max_trials, and up to kTrialExtension times as many
// while the draws found fewer than min_hypotheses poses. Among many
// look-alikes the W candidates of a query feature spread over them and few
// draws pair up in one model (1000 procedural models: about 100 hypotheses
// in 800 draws, against 300-400 at 56). A pose refused for its tilt
// (max_tilt_deg) was found all the same: the draws did pair up, and
// counting only the verified ones extended a flight-preset truck's draws
// and focused search, 45 -> 150 M instructions (docs/results.md 11k).
// A sparse scan's budget is ctx.trial_scale times the configured one
// (sparse_search.hpp), at most kMaxTrials: the extension's kTrialExtension
// times it stays within the draws' 32-bit count.
uint64_t trial_budget(const SearchContext& ctx) {
  const uint64_t b = static_cast<uint64_t>(ctx.trial_scale) * ctx.cfg.max_trials;
  return b < kMaxTrials ? b : kMaxTrials;
}

bool keep_drawing(const SearchContext& ctx) {
  const uint64_t drawn = ctx.stats.trials, budget = trial_budget(ctx);
  return drawn < budget ||
         (drawn < kTrialExtension * budget &&
          ctx.stats.poses_found() < static_cast<uint64_t>(ctx.trial_scale) * ctx.cfg.min_hypotheses);
}

// The candidates are spread over look-alikes when their perplexity (the
// number of models they name, exp(H)) averages more than this: two
// features then rarely hold candidates of one model. Harmonic mean over the
// features with candidates, W = 50: 12-19 on the demo's 112 queries (56
// models), 38-45 on 56 queries at 1000 procedural models (143 look-alikes
// per family). Never reached with W below it.
constexpr float kSpreadPerplexity = 25.0f;

bool candidates_spread(const SearchContext& ctx) {
  const float inverse_perplexity_sum = ctx.buf.cumulative[ctx.query.count - 1u];  // sum of exp(-H)
  return inverse_perplexity_sum * kSpreadPerplexity < static_cast<float>(ctx.stats.salient_features);
}

// Candidates and saliency weights of every query feature.
void gather_candidates(SearchContext& ctx, uint32_t w) {
  RecognizerBuffers& b = ctx.buf;
  SearchStats ss;
  float running = 0.0f;
  for (uint32_t l = 0; l < ctx.query.count; ++l) {
    Candidate* list = ctx.candidates_of(l);
    uint32_t n =
        b.searcher.search(ctx.db, ctx.query.spins + static_cast<size_t>(l) * ctx.query.dims, w, list, &ss);
    b.candidate_count[l] = n;
    ctx.stats.candidates += n;
    // exp(-H) = 1 / perplexity: a feature whose candidates name one model is
    // drawn as often as one spread evenly over e.g. 20 models, 20 times.
    if (n > 0) {
      running += std::exp(-candidate_entropy(ctx.db, list, n));
      ++ctx.stats.salient_features;
    }
    b.cumulative[l] = running;
  }
  ctx.stats.bucket_entries = ss.entries_scanned;
  ctx.stats.bucket_scan_truncated = ss.truncated;
}

// Look-alike doublets (cfg.lookalike_box_l1): each of feature k's candidates
// pairs with at most this many of feature l's candidates in look-alikes, the
// nearest in spin image that pass the cascade (the lists are sorted by L1).
// Near-identical models hold near-identical features, so every further one
// would give nearly the same pose again.
constexpr uint32_t kLookalikePairsPerCandidate = 1;
// ... and a draw verifies at most this many look-alike poses: among
// identical copies every candidate has a look-alike partner, and one pose
// would be verified W times over (spread queries at 1000 procedural models
// verify 2-3 per draw).
constexpr uint32_t kLookalikePairsPerDraw = 4;

// Whether candidates of look-alikes a != b may still form a doublet
// (verified as a's), `pairs` and `draw_pairs` look-alike pairs in.
bool lookalike_pair_allowed(const SearchContext& ctx, uint16_t a, uint16_t b, uint32_t pairs,
                            uint32_t draw_pairs) {
  return pairs < kLookalikePairsPerCandidate && draw_pairs < kLookalikePairsPerDraw &&
         boxes_within(ctx.db.model(a), ctx.db.model(b), ctx.cfg.lookalike_box_l1);
}

// Every same-model candidate pair of features (k, l), and with spread
// candidates look-alike pairs; false once the budget is spent.
bool enumerate_pairs(SearchContext& ctx, uint32_t k, uint32_t l, const DoubletShape& shape,
                     const HypothesisCaps& caps) {
  const Candidate* ck = ctx.candidates_of(k);
  const Candidate* cl = ctx.candidates_of(l);
  const uint16_t* models = ctx.db.feature_models();
  const bool lookalikes = ctx.stats.candidates_spread && ctx.cfg.lookalike_box_l1 > 0.0f;
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

}  // namespace

void run_bran(SearchContext& ctx) {
  gather_candidates(ctx, ctx.cfg.top_w);
  if (ctx.stats.salient_features < 2u) return;
  ctx.stats.candidates_spread = candidates_spread(ctx);
  ctx.cumulative = ctx.buf.cumulative;
  const HypothesisCaps caps{ctx.cfg.max_hypotheses, 0xFFFFFFFFu};
  while (keep_drawing(ctx)) {
    ++ctx.stats.trials;
    uint32_t k = 0, l = 0;
    DoubletShape shape;
    if (!draw_stable_doublet(ctx, &k, &l, &shape)) continue;
    ++ctx.evidence.draws;
    if (!enumerate_pairs(ctx, k, l, shape, caps)) break;
    if (evidence_says_stop(ctx)) {
      ctx.stats.stopped_on_evidence = true;
      break;
    }
  }
  transfer_poses(ctx);
  // Candidates spread over look-alikes, or so few poses that the draws were extended.
  if ((ctx.stats.candidates_spread || ctx.stats.trials > trial_budget(ctx)) && !ctx.stats.budget_exhausted)
    focus_on_leaders(ctx);
}

}  // namespace spinhash
