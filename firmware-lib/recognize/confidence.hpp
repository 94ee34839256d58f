// What a Result promises (not in the paper): the look-alike group and the
// `confident` flag, from the ranking and the first model's fit to the scan.
#pragma once
#include <cstdint>

#include "match/likelihood.hpp"
#include "match/oriented_point.hpp"
#include "spinhash/blob_format.hpp"
#include "spinhash/database.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash {

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
// same scan without ground reached it (docs/results.md 11f). HiddenEnds says
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

// The look-alike margin per sqrt(feature): min_margin, twice that when the
// candidates spread over many look-alikes (stats.candidates_spread).
float lookalike_margin(const Result& r, const RecognizerConfig& cfg);
// The lead per sqrt(feature) a confident answer needs: lookalike_margin(),
// times (full_coverage / stats.surface_coverage)^2 when the scan shows less
// than full_coverage of the first model's upward surface: an occluder hides
// what tells near-identical models apart, and the few features left in view
// lead by little more by chance than by the model's shape; and times
// sqrt(kFullModelDensity / stats.scan_density) when the scan is sparser
// than that.
float confident_margin(const Result& r, const RecognizerConfig& cfg);

// The leading models within min_margin x sqrt(features) log-likelihood of
// the first, twice that when the candidates spread over many look-alikes
// (stats.candidates_spread); 1 for SIND, whose votes are no likelihoods; 0
// without a ranking.
uint32_t lookalike_group_size(const Result& r, const RecognizerConfig& cfg, uint32_t features);

// The largest residual F (residual_structure()) a confident answer may
// leave: max_residual_f, 0.8 x that when the candidates spread over many
// look-alikes (stats.candidates_spread).
float residual_limit(const Result& r, const RecognizerConfig& cfg);

// The first model explains enough of the query, well enough, stands alone
// (its look-alike group is itself) and leads by confident_margin(), is
// pinned by the scan's extent (`fit` under its pose within
// max_extent_shortfall / max_extent_overhang) and
// leaves residuals that are noise, not a shape (`residual_f`, the F of
// residual_structure(), at most residual_limit()).
bool is_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                  float residual_f);

// The least density, object points (after terrain removal) per m^2 of the
// model box's top the scan spans, at which a model is named confidently. A
// survey at 10-30 points per m^2 of ground returns 100-550 points of a car
// (issue 28: 100 real cars at 26 per m^2), about 12-70 per m^2 of its 8 m^2
// top with the sides; the simulated 3-view scans at 0.35 m (10-30 here) of
// vehicles outside the database were confident 5 % of the time without
// this gate. 50, not 75: the 0.15 m scans, 40 % occluded, with ground
// (docs/results.md 9n) fall to 60-75 and lost half their confident answers
// at 75, while above 30 the unknown vehicles' confident share (near twins,
// 10-20 %) does not fall with density: the gate answers sparsity only.
constexpr float kMinModelDensity = 50.0f;
// The density (scan_density()) the margin was calibrated at, and below
// which it grows as 1 / sqrt(density): a spin image is a histogram of about
// density x its support's area points, so the per-feature log-likelihood,
// and the lead's spread with it, grows noisier as 1 / sqrt(density). 130:
// the least the fleet's scans that set min_margin reach (0.10 m, 40 %
// occluded: 5th percentile 130 per m^2, median 170). The 20 real cars'
// scans at 0.15 m fall to 57-74 when 40 % occluded; there 10 of 736
// confident answers were wrong on 24 seeds, now 3 of 562 (docs/results.md
// 11r).
constexpr float kFullModelDensity = 130.0f;

// How densely the scan samples the vehicle: the object's points (after
// terrain removal) per m^2 of the part of the model box's top the scan
// spans (ExtentFit::seen_area), so that occlusion does not read as sparsity.
float scan_density(const ExtractStats& s, const ExtentFit& fit);

// Whether a scan this dense carries the evidence to name one model
// (kMinModelDensity): a sparse survey tells a car from a bus, not one sedan
// from another.
bool dense_enough_for_model(float density);

// The classes of r's ranking, each scored by its first model in the ranking
// (its best but for the twins order_twins_by_residuals swaps), best first
// (ties by class id); returns how many (at most kVehicleClassCount).
uint32_t rank_classes(const Database& db, const Result& r, RankedClass* out);

// The first class stands alone: its best model explains the query as
// is_confident() asks (inliers, log-likelihood), the scan does not reach
// beyond that model's box by more than the class allows (`fit`), the next
// class scores at least min_margin x sqrt(features) lower, the database
// holds a second class to tell it from, the class is not "unclassified",
// and the scan is dense enough (kMinClassDensity) with kMinClassFeatures.
// The recognizer then also asks the scan's shape to lie within the class's
// envelope (class_envelope.hpp).
bool is_class_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                        float density);

}  // namespace spinhash
