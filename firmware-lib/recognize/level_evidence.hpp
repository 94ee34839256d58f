// The evidence of each answer level (answer_levels.h), its flag and the
// answer's level (not in the paper). Every level's evidence is a scalar the
// core computes from a result, the same at build time, when `spinhash build`
// fits the thresholds from the database's own models, and on board; hard
// prerequisites stay priors of the recognizer's settings: a failed one makes
// the evidence kNoEvidence, which no threshold reaches.
#pragma once
#include <cstdint>
#include <limits>

#include "recognize/class_envelope.hpp"
#include "recognize/confidence.hpp"
#include "recognize/search_context.hpp"
#include "spinhash/calibration.hpp"
#include "spinhash/database.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash {

constexpr float kNoEvidence = -std::numeric_limits<float>::infinity();
// The lead of an answer without a runner-up: no score of the database
// opposes it.
constexpr float kUnopposed = std::numeric_limits<float>::infinity();

// Model level: the first model's lead over the runner-up per sqrt(query
// features), divided by the shape factors of confident_margin() that are
// not density (the look-alike spread, the coverage): the lead in units of
// what the scan's shape lets a look-alike gain by chance. Prerequisites:
// the tests of is_confident() but its margin (inliers, mean log-likelihood,
// a look-alike group of 1, the extent fit, the residual F), and some of the
// model's upward surface seen.
float model_evidence(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                     float residual_f);

// Class level: the first class's lead over the next per sqrt(query
// features). Prerequisites: those of is_class_confident() but its margin,
// and the scan within the class's envelope (`within_envelope`).
float class_evidence(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                     float density, bool within_envelope);

// The groups of r's ranking (model_group() of each model), each
// scored by its first model in the ranking, best first (ties by group id);
// returns how many (at most kVehicleGroupCount).
uint32_t rank_groups(const Database& db, const Result& r, RankedGroup* out);

// What the class and group levels measure of a posed model: the scan's
// extent fit to its box, the scan's density under that fit, and the scan's
// shape in its frame.
struct MemberFit {
  ExtentFit fit;
  float density = 0.0f;
  ScanShape shape;
};
MemberFit member_fit(const SearchContext& ctx, uint32_t model);

// Group level: the first group's lead over the next per sqrt(query
// features) (kUnopposed when no other group is ranked). Prerequisites: a
// group other than none, and one of its posed models among the first
// classes.group_fit_models of the ranking, in ranking order, that explains
// the scan (model_explains_scan(): a vehicle the database lacks, shorter or
// longer than the group's best-scoring member, may fit another member's
// box) with the scan within the group's envelope. `known` is the fit of the
// model at ranking position `known_rank` (the class leader's, measured
// already; any other rank, e.g. UINT32_MAX: none).
float group_evidence(const SearchContext& ctx, uint32_t known_rank, const MemberFit& known);

// Vehicle level: whether the best model explains the scan as a vehicle,
// not a tree, wall, crate or building: its mean log-likelihood per query
// feature (how near the scan's points lie to the model's surface, with
// agreeing normals and spin images), plus the log of the share of the
// model's box top the scan spans under its pose (ExtentFit::seen_area):
// the log of a per-feature likelihood times the part of the vehicle seen.
// A crate or a wall is explained by one face of a vehicle nearly as well
// as a vehicle is, but spans a tenth of its top; a tree or a building spans
// all of it, and its points lie off the model's surface. On the procedural
// fleet's calibration scans this separated the scene simulator's clutter
// from the vehicles (known and unknown) better than the log-likelihood
// alone, the inlier share or the surface coverage, and as well as a
// penalty in metres on the extent misfit, which needs a weight and grows
// with a vehicle's size. Prerequisites: a pose, and what the group level
// asks before its lead (assess_coarse_levels: a posed member of the first
// group explains the scan and the group's envelope holds it), because
// vehicle-sized non-vehicles (sheds, heaps, bushes, freight containers)
// score as vehicles do here; kNoEvidence without them or when the scan
// spans none of the top.
float vehicle_evidence(const Result& r, uint32_t features, const ExtentFit& fit,
                       const blob::ModelRecord& model);

// The flag without a fitted table (a blob built with --no-calibration):
// the stage parameters as they decided before calibration, the priors the
// fit replaces. The model level: confidence.min_margin times
// sqrt(full_model_density / density) below that density, and no flag below
// min_model_density; class and group: min_margin; the vehicle level, which
// had no flag: min_mean_log_likelihood, the floor of a confident model's
// fit, over the whole top.
bool prior_confident(AnswerLevel level, float evidence, float density, const RecognizerConfig& cfg);

// The flag of `level`: the database's fitted threshold for `pass` at the
// scan's density, else the priors.
bool level_confident(const Database& db, AnswerPass pass, AnswerLevel level, float evidence, float density,
                     const RecognizerConfig& cfg);

// The first entries of an answer's rankings (null: that ranking is empty).
struct AnswerLeaders {
  const RankedModel* model = nullptr;
  const RankedClass* vehicle_class = nullptr;
  const RankedGroup* group = nullptr;
};

// The most specific confident level (`levels`, kCalibratedLevels of them)
// whose coarser levels are all confident and consistent: the first model is
// of the first class, whose best model is of the first group (for a class
// in no group, that model's own group). A scene, which adds its
// own size tests to the model and class flags, asks it again with them.
AnswerLevel answer_level(const Database& db, const LevelAnswer* levels, const AnswerLeaders& first);
AnswerLevel answer_level(const Database& db, const Result& r);

// The model level (the confidence stage, after the first model's
// coverage and scan density): its evidence under `fit` (the first model's
// extent fit), its flag for `pass`, and `confident` as that flag.
void assess_model_level(const SearchContext& ctx, const ExtentFit& fit, AnswerPass pass);

// The coarser levels (the classes stage, after the class ranking): the
// group ranking, the vehicle, group and class levels' evidence and flags
// for `pass`, `class_confident` as the class level's flag, and the level.
void assess_coarse_levels(const SearchContext& ctx, AnswerPass pass);

}  // namespace spinhash
