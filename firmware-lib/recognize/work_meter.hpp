// The work a pass has done, in units of about one LSH entry scanned (60-115
// instructions on x86-64 and aarch64), from the counts its stages keep: what
// RecognizerConfig::max_work caps. Deterministic (counts, not time), so the
// cap stops a query at the same point on every target. The weights are the
// instructions of each counted step over an LSH entry's (docs/budgets.md
// gives the instructions per unit as measured). Every pose scored counts,
// on the hypothesis loop's features, V = min(verify_features, F) of the
// query's F (hypotheses, transferred, carried and screened poses), or on
// all F (rescored poses and refinements). The cap is checked between
// stages, before each candidate pair and after each query feature's bucket
// scan, and the extraction's charge (kWorkPerPoint a point equalised) is
// known before its normals and spin images: a pass that would reach the cap
// there is charged it and stops, so a query passes the cap by at most one
// feature's bucket scan, one pair, or the transfer or refine stage it has
// begun (their poses bounded by their settings, their instructions measured
// in docs/budgets.md), and the uncounted equalisation of its cloud.
#pragma once
#include <cstdint>

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

// The query has spent its cap (the earlier passes' work and this one's).
inline bool work_capped(const SearchContext& ctx) {
  return ctx.work_before + pass_work(ctx.stats, ctx.params) >= ctx.work_cap;
}

// The most points the extraction may equalise and still leave the query
// under its cap (before it, no pose is scored: its charge is the points').
inline uint32_t extraction_room(const SearchContext& ctx) {
  const uint64_t spent = ctx.work_before + pass_work(ctx.stats, ctx.params);
  if (spent >= ctx.work_cap) return 0;
  const uint64_t room =
      (ctx.work_cap - spent - 1u) / kWorkPerPoint;  // n points: n x kWorkPerPoint < the rest
  return room < UINT32_MAX ? static_cast<uint32_t>(room) : UINT32_MAX;
}

}  // namespace spinhash
