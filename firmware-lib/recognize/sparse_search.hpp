// More doublet draws for a sparse scan (issue 28; not in the paper). At
// 10-30 points per m^2 a car returns 100-250 features whose spin images are
// sparse and noisy: BRAN's draws often verify no model of the vehicle's
// class at all (13 of the 17 class misses of section 11's sparse scans,
// docs/results.md 11b), while such a scan is cheap to search (about 23 ms a
// query against 70-110 ms on dense scans). Below the density that names a
// model (kMinModelDensity) the draws' budget is kSparseTrialScale times the
// configured one (max_trials, min_hypotheses; max_hypotheses still caps the
// poses).
#pragma once
#include <cstdint>

#include "match/likelihood.hpp"

namespace spinhash {

// Four times the draws: on section 11's 241 3-view scans at 10-30 per m^2
// the class right first went from 224 to 229 (92.9 -> 95.0 %) for a median
// 23 -> 27 ms (docs/results.md 11c); twice (--trials 1600
// --min-hypotheses 400) gave 225.
constexpr uint32_t kSparseTrialScale = 4;

// Object points per m^2 of the query's footprint before any pose: the
// features' extent along their principal horizontal axes (at least
// kMinFootprint), the measure the confidence gate takes under a pose.
constexpr float kMinFootprint = 0.25f;  // m^2: a degenerate footprint counts as this
float footprint_density(const QueryFeatures& query, uint32_t points);

// kSparseTrialScale below kMinModelDensity, else 1.
uint32_t trial_scale(float footprint_density);

// A sparse scan's LSH lookups look at kSparseScanScale times
// max_bucket_scan bucket entries, up to kMaxSparseBucketScan (and never
// fewer than max_bucket_scan). Its coarse, noisy spin images fall in
// crowded buckets (a roof's, which every bus fills), whose sampled share
// can hold no feature of the vehicle: an APC scanned with 5 cm of noise was
// named a bus with no APC posed at all. On bare survey views at 12-21
// points per m^2 the class right first gained a net 9 and 15 of 560 scans
// on two draws (docs/results.md 11j), most of them APCs and trucks named
// buses. Its features share the dense query's total, max_features x
// max_bucket_scan, so the query's bound stays.
constexpr uint32_t kSparseScanScale = 4;
constexpr uint32_t kMaxSparseBucketScan = 4096;

// The most bucket entries a lookup scans under max_bucket_scan: the seen
// set's bound (LshSearcher::carve).
uint32_t sparse_bucket_scan(uint32_t max_bucket_scan);

// The bucket entries each lookup of a query with `features` features scans.
uint32_t bucket_scan(uint32_t max_bucket_scan, uint32_t max_features, float footprint_density,
                     uint32_t features);

}  // namespace spinhash
