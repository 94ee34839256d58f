// More doublet draws and a wider LSH scan for a sparse scan (not in the
// paper). At 10-30 points per m^2 a car returns 100-250 features whose spin
// images are sparse and noisy: BRAN's draws often verify no model of the
// vehicle's class at all, while such a scan is cheap to search. Below
// CandidatesParams::sparse_density the draws' budget is
// DrawsParams::sparse_trial_scale times the configured one (max_trials,
// min_hypotheses; max_hypotheses still caps the poses), and the LSH lookups
// scan more bucket entries: a sparse scan's coarse, noisy spin images fall
// in crowded buckets (a roof's, which every bus fills), whose sampled share
// can hold no feature of the vehicle.
#pragma once
#include <cstdint>

#include "match/likelihood.hpp"
#include "spinhash/config.hpp"

namespace spinhash {

// Object points per m^2 of the query's footprint before any pose: the
// features' extent along their principal horizontal axes (at least
// kMinFootprint), the measure the confidence gate takes under a pose.
constexpr float kMinFootprint = 0.25f;  // m^2: a degenerate footprint counts as this
float footprint_density(const QueryFeatures& query, uint32_t points);

// A scan of this footprint density is searched as a sparse one
// (CandidatesParams::sparse_density).
bool searched_as_sparse(const StageParams& p, float footprint_density);

// DrawsParams::sparse_trial_scale for a sparse scan, else 1.
uint32_t trial_scale(const StageParams& p, float footprint_density);

// A sparse scan's lookups look at sparse_scan_scale times max_bucket_scan
// bucket entries, up to max_sparse_bucket_scan (and never fewer than
// max_bucket_scan). Its features share the dense query's total,
// max_features x max_bucket_scan, so the query's bound stays.
// The most bucket entries a lookup scans under `p`: the seen set's bound
// (LshSearcher::carve).
uint32_t sparse_bucket_scan(const CandidatesParams& p);

// The bucket entries each lookup of a query with `features` features scans.
uint32_t bucket_scan(const StageParams& p, uint32_t max_features, float footprint_density, uint32_t features);

}  // namespace spinhash
