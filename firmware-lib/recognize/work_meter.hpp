// The work a pass has done, in units of about one LSH entry scanned (60-115
// instructions on x86-64 and aarch64), from the counts its stages keep: what
// RecognizerConfig::max_work caps. Deterministic (counts, not time), so the
// cap stops a query at the same point on every target. The weights are the
// instructions of each counted step over an LSH entry's (docs/budgets.md
// gives the instructions per unit as measured). Every pose scored counts,
// on the hypothesis loop's features, V = min(verify_features, F) of the
// query's F (hypotheses, transferred, carried and screened poses), or on
// all F (rescored poses and refinements).
//
// The cap is checked between stages, after each query feature's bucket
// scan, before each candidate pair and each transferred pose, and in the
// refine stage before each leader's rescoring, each refinement (a model's
// turn end to end its own), each lending round and each look-alike's
// lending. The extraction's charge (kWorkPerPoint a point equalised) is
// known before its normals and spin images: a pass that would reach the cap
// there is charged it and stops (what it then passes the cap by is counted,
// not run). Otherwise a query passes its cap by at most the one step in
// which it reached it, each bounded by the configuration:
// - a feature's bucket scan: max_bucket_scan entries (a sparse scan's up to
//   max_sparse_bucket_scan);
// - a candidate pair (kWorkPerPairCheck) and its pose, or a transferred
//   pose: V features;
// - in the refine stage, at most refine_step_work: a leader's rescoring
//   (F), its refinement as found (refine_iterations x F) or turned (2
//   screens on V, a rescoring and refine_iterations x F), a lending round's
//   screen of the first model's pose (V), or one look-alike's lending
//   (kEndAlignedPoses screens on V, a rescoring and refine_iterations x F);
// beside the carried poses (carry_models, V each), verified even when the
// cap was reached before them (an answering stage, stages.hpp). No unit
// counts the equalisation of the cloud, the focused search's per-model
// candidate search (one model's may follow the step that reaches the cap),
// SRAN's, the least squares of a refinement, the upward surface of each
// finalised model (its features) or the ranking: their instructions are
// measured, not bounded here (docs/budgets.md).
#pragma once
#include <cstdint>

#include "match/refine_pose.hpp"
#include "recognize/search_context.hpp"

namespace spinhash {

constexpr uint64_t kWorkPerBucketEntry = 1;      // an LSH entry scanned: its key and spin distance
constexpr uint64_t kWorkPerPairCheck = 2;        // a candidate pair through the doublet cascade
constexpr uint64_t kWorkPerVerifiedFeature = 4;  // a query feature scored under a pose
constexpr uint64_t kWorkPerPoint = 150;          // a point equalised: its normal, grids and spin share

// The pass's work so far (its statistics and its settings).
inline uint64_t pass_work(const RecognitionStats& s, const RecognizerConfig& pass) {
  const uint64_t verify = pass.draws.verify_features, features = s.extract.features;
  const uint64_t on_subset =
      static_cast<uint64_t>(s.draws.hypotheses) + s.transfer.transferred + s.carry.carried + s.refine.screens;
  const uint64_t on_all = static_cast<uint64_t>(s.refine.rescores) + s.refine.refinements;
  return kWorkPerPoint * s.extract.points_equalised + kWorkPerBucketEntry * s.candidates.bucket_entries +
         kWorkPerPairCheck * s.draws.pair_checks +
         kWorkPerVerifiedFeature * (on_subset * (verify < features ? verify : features) + on_all * features);
}

// The query's work so far: the earlier passes' and this one's. Out of line
// (work_meter.cpp): the cap is checked at a dozen places, and the
// bare-metal code budget counts each copy (docs/budgets.md).
uint64_t query_work(const SearchContext& ctx);

// The query has spent its cap.
inline bool work_capped(const SearchContext& ctx) { return query_work(ctx) >= ctx.work_cap; }

// The most points the extraction may equalise and still leave the query
// under its cap (before it, no pose is scored: its charge is the points').
inline uint32_t extraction_room(const SearchContext& ctx) {
  const uint64_t spent = query_work(ctx);
  if (spent >= ctx.work_cap) return 0;
  const uint64_t room =
      (ctx.work_cap - spent - 1u) / kWorkPerPoint;  // n points: n x kWorkPerPoint < the rest
  return room < UINT32_MAX ? static_cast<uint32_t>(room) : UINT32_MAX;
}

// The most a step of the refine stage between two checks of the cap counts
// (one look-alike's lending, the largest), for `features` query features:
// the most a query that reaches its cap there passes it by.
inline uint64_t refine_step_work(uint64_t features, const RecognizerConfig& pass) {
  const uint64_t verify = pass.draws.verify_features < features ? pass.draws.verify_features : features;
  return kWorkPerVerifiedFeature *
         ((1u + pass.refine.refine_iterations) * features + uint64_t{kEndAlignedPoses} * verify);
}

}  // namespace spinhash
