// The confidence stage (not in the paper; stage_fields.h: ConfidenceParams):
// what a Result promises, the look-alike group and the `confident` flag,
// from the ranking and the first model's fit to the scan.
#pragma once
#include <cstdint>

#include "match/likelihood.hpp"
#include "match/oriented_point.hpp"
#include "recognize/search_context.hpp"
#include "spinhash/blob_format.hpp"
#include "spinhash/database.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash {

// The first model's surface coverage and scan density (stats.confidence),
// and the tests of is_confident() under its pose; the residuals' structure
// is measured only for an answer that passes the others.
Status confidence_stage(SearchContext& ctx);

// How well the query's extent matches the model's box under `pose` (model
// frame -> query frame), in metres: `shortfall` is the most the query stops
// short of an end of the box along x or y or of its top (what a longer,
// wider or taller look-alike could hide there); `overhang` the most the
// query's second outermost feature reaches beyond one of them (a single
// stray feature is noise or a ground remnant). The bottom is left out:
// terrain removal cuts it. 0 / 0 for a query without features.
//
// Terrain removal also cuts what of the ends lies low: a sports car's nose
// or a bumper under the removed band reaches past everything above it, and
// a scan with its ground stopped 0.22-0.29 m short of such an end where the
// same scan without ground reached it. HiddenEnds says
// per side face (-x, +x, -y, +y) how far the model's outermost feature lies
// beyond its outermost feature above the band; the shortfall at that face
// counts only beyond it. All zero when nothing was removed.
struct HiddenEnds {
  float face[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // m
};
// Of model `model`'s features (model frame), those within `band` m of the
// box's bottom against the rest. O(model features).
HiddenEnds hidden_ends(const Database& db, uint32_t model, float band);
struct ExtentFit {
  float shortfall = 0.0f;
  float overhang = 0.0f;
  // m^2 of the model box's top (x by y) that the query's features span: the
  // part of the vehicle the scan shows (an occluder hides the rest).
  float seen_area = 0.0f;
};
ExtentFit extent_fit(const QueryFeatures& query, const blob::ModelRecord& model, const RigidPose& pose,
                     const HiddenEnds& hidden = HiddenEnds{});

// The parameters below are ConfidenceParams (cfg.confidence) unless named.
// Most wrong answers are a look-alike of the right one, which comes second
// a little behind: eq. 7 sums n per-feature terms, so the lead grows as n
// and its spread as sqrt(n), and the margin is a z-score.

// The look-alike margin per sqrt(feature): min_margin, spread_margin_factor
// times that when the candidates spread over many look-alikes
// (stats.candidates.spread: the runner-up is then the best of many
// near-identical models, which lies some spreads above their mean).
float lookalike_margin(const Result& r, const RecognizerConfig& cfg);
// The lead per sqrt(feature) a confident answer needs: lookalike_margin(),
// times (full_coverage / surface_coverage)^2 when the scan shows less than
// full_coverage of the first model's upward surface: an occluder hides what
// tells near-identical models apart, and the few features left in view lead
// by little more by chance than by the model's shape; and times
// sqrt(full_model_density / scan_density) when the scan is sparser than
// that: a spin image is a histogram of about density x its support's area
// points, so the per-feature log-likelihood, and the lead's spread with it,
// grows noisier as 1 / sqrt(density).
float confident_margin(const Result& r, const RecognizerConfig& cfg);

// The leading models within lookalike_margin() x sqrt(features)
// log-likelihood of the first; 1 for SIND, whose votes are no likelihoods; 0
// without a ranking.
uint32_t lookalike_group_size(const Result& r, const RecognizerConfig& cfg, uint32_t features);

// The largest residual F (residual_structure()) a confident answer may
// leave: max_residual_f, spread_residual_factor x that when the candidates
// spread over many look-alikes (most alternatives then differ from the
// first by one patch: a weak structure in the residuals).
float residual_limit(const Result& r, const RecognizerConfig& cfg);

// The first model explains enough of the query (min_inlier_fraction),
// well enough (min_mean_log_likelihood), stands alone (its look-alike group
// is itself) and leads by confident_margin(), is pinned by the scan's extent
// (`fit` under its pose within max_extent_shortfall / max_extent_overhang:
// a scan that misses a vehicle's end is explained as well by a longer
// look-alike) and leaves residuals that are noise, not a shape
// (`residual_f`, the F of residual_structure(), at most residual_limit()).
bool is_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                  float residual_f);

// How densely the scan samples the vehicle: the object's points (after
// terrain removal) per m^2 of the part of the model box's top the scan
// spans (ExtentFit::seen_area), so that occlusion does not read as sparsity.
float scan_density(const RecognitionStats& s, const ExtentFit& fit);

// Whether a scan this dense carries the evidence to name one model
// (min_model_density): a sparse survey tells a car from a bus, not one sedan
// from another.
bool dense_enough_for_model(const RecognizerConfig& cfg, float density);

}  // namespace spinhash
