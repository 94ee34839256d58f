// Parameters of feature extraction (fixed per database, stored in the blob)
// and of recognition (chosen per call). Symbols in comments are the paper's.
#pragma once
#include <cstdint>

namespace spinhash {

// How a cloud becomes oriented spin-image features. The database stores the
// values it was built with; queries are described with the same values.
struct FeatureParams {
  float cloud_voxel = 0.08f;        // m: density-equalising voxel before anything else
  float normal_radius = 0.40f;      // m: PCA neighbourhood for normals (wide enough for 10 cm noise)
  float basis_spacing = 0.25f;      // m: voxel size for uniform basis-point sampling
  float support_radius = 1.0f;      // m: spin image support (paper: 1 m)
  uint32_t bins_alpha = 10;         // radial bins (paper: 10x10)
  uint32_t bins_beta = 10;          // elevation bins, beta in [-R, R)
  float support_angle_deg = 60.0f;  // neighbours whose normal differs more are ignored; >= 180 disables
  float spin_quant_scale =
      1000.0f;  // quantised bin = min(255, round(value * scale)), value normalised to sum 1
};

inline uint32_t spin_dims(const FeatureParams& p) { return p.bins_alpha * p.bins_beta; }  // d

enum class Mode : uint8_t {
  kBran = 0,  // batch RANSAC over the joint LSH index (section 9)
  kSran = 1,  // sequential per-model RANSAC (baseline)
  kSind = 2,  // spin-image indexing by LSH voting, no geometry (baseline)
};

// Recognition settings. Capacities (max_*) size the workspace; the rest are
// thresholds and budgets. Defaults are the paper's setting where it gives one.
struct RecognizerConfig {
  Mode mode = Mode::kBran;
  uint64_t seed = 1;  // deterministic sampling

  // Capacities: inputs above them are refused (points) or thinned (features).
  uint32_t max_points = 32768;       // raw query points used (more: thinned evenly, or refused)
  bool thin_large_clouds = true;     // false: a cloud above max_points is refused (kTooManyPoints)
  uint32_t max_features = 1024;      // s: query basis points kept
  uint32_t max_models = 2048;        // m: database models supported by this workspace
  uint32_t max_spin_dims = 256;      // d: largest spin image (bins_alpha * bins_beta) supported
  float query_basis_spacing = 0.0f;  // m between query basis points; 0: the database's spacing
  // m: the query's density-equalising voxel (FeatureParams::cloud_voxel for
  // the query only); 0: the database's (0.08 m by default). A coarser voxel
  // averages a dense scan (0.05 m spacing) down to the points of a sparser
  // one: fewer instructions per query, answers that move (issue 29;
  // docs/results.md section 9q measures it; the flight preset of
  // spinhash/presets.hpp uses it).
  float query_cloud_voxel = 0.0f;

  // Airborne scans hold the ground around the vehicle, which no model has.
  // When the cloud stands on terrain (z up; level or sloped to 18 degrees,
  // with bumps; geometry/object_ground.hpp, docs/api.md), the points within 4.5
  // sigma of the ground's measured roughness above it are dropped, but at
  // most this height (not in the paper). 0 keeps every point.
  float ground_clearance = 0.25f;  // m

  // Spin-image pruning (section 5).
  uint32_t top_w = 50;              // W for BRAN (paper: 50)
  uint32_t top_w_sran = 5;          // W for SRAN, per model (paper: 5)
  uint32_t top_w_sind = 1;          // W for SIND (paper: 1)
  uint32_t max_bucket_scan = 1024;  // LSH entries scanned per query feature, at most (shared by the L tables)

  // Doublets (section 7, Figure 5 and eq. 3).
  float d_min = 0.5f;           // d_min, m
  float theta_min_deg = 10.0f;  // theta_min between the two normals
  float tol_distance = 0.30f;   // |d - d'| allowed, m
  float tol_angle_deg = 25.0f;  // |a - a'|, |b - b'|, |c - c'| allowed
  float tol_handedness = 0.5f;  // |t - t'| allowed, t = (n1 x n2) . u  (rejects mirror images)
  // A doublet's pose is verified only when it tilts the model's up axis (its
  // z) at most this far from the query's z (not in the paper). An airborne
  // vehicle stands on its wheels on terrain of up to 15-20 degrees, and the
  // query is georeferenced, z up. The paper's doublets fix no axis, and on
  // sparse noisy scans most verified poses laid a bus on its side over an
  // APC's roof (docs/results.md 11k). The bound is on the doublets' poses;
  // refinement may turn one a few degrees further. 180: any pose (clouds
  // without z up).
  float max_tilt_deg = 45.0f;

  // Likelihood (section 8, eqs. 4-7).
  float sigma = 0.15f;  // sigma, m: sensor noise plus basis-point sampling offset
  // sigma of the final ranking's residuals, m: the leading models are scored
  // by each query feature's distance to the model's surface (along the
  // nearest model feature's normal), which has no basis-point sampling
  // offset left in it; the range noise alone (0.05-0.10 m).
  float sigma_surface = 0.10f;
  float delta = 0.30f;        // Delta, m: inlier radius
  float delta_max = 0.60f;    // Delta_max, m: spread of outliers
  float eta_max_deg = 35.0f;  // eta_max: normal agreement
  float spin_lambda = 0.5f;   // p_s = exp(-L1 / lambda), L1 of sum-normalised spin images

  // Hypotheses are scored on at most this many query features (evenly
  // spread; the paper's "all or a percentage of all query features"); the
  // leading models are then rescored on all of them. 256: 128 (the default
  // in stop 29, 5 % fewer instructions at 56 models, the same accuracy on the
  // fleet, its families and 1 000 models) lost on the independent real cars
  // (docs/results.md 11f: 10 cm noise without ground, right first 100 -> 99 %,
  // confident 90 -> 86 of the right) and on section 11's sparse classes.
  uint32_t verify_features = 256;

  // Look-alike pose transfer (not in the paper; BRAN): the poses of the
  // leading models are also verified on the models whose bounding boxes are
  // nearest theirs (this many per pose), for look-alikes crowded out of the
  // W candidates in a large database. Pays off when models share a frame convention
  // (CAD libraries, our fleets); 0 turns it off (the paper's BRAN).
  uint32_t transfer_models = 32;

  // Focused search (not in the paper; BRAN): when the candidates are spread
  // over many look-alikes (their perplexity averages over 25 models), or
  // the draws had to be extended past max_trials (min_hypotheses), this
  // many leading models each get a short RANSAC of their own, as SRAN gives
  // every model (its top_w_sran candidates per query feature, kFocusTrials
  // draws), so the true model among near-identical ones gets its own pose
  // before the final ranking. 0 turns it off (the paper's BRAN).
  uint32_t focus_models = 16;

  // Look-alike doublets (not in the paper; BRAN): when the candidates are
  // spread over many look-alikes, two query features rarely hold candidates
  // of one model, so the true model gets few doublets. A doublet may then
  // also pair a candidate of one model with one of a look-alike whose
  // bounding box (each in its own frame) differs by at most this L1 sum over
  // the box's 6 coordinates, in metres: their surfaces nearly coincide, so
  // the pose fits both, and it is verified as the first candidate's model.
  // Each first candidate pairs with its one nearest look-alike candidate
  // that passes the cascade. 0 turns it off (the paper's BRAN).
  float lookalike_box_l1 = 0.6f;

  // Least-squares refinement of the best few models' poses over their
  // inliers after the hypothesis loop (not in the paper; BRAN and SRAN).
  bool refine_poses = true;

  // "No confident match" unless the best model explains at least this share
  // of the query features within Delta and its log-likelihood per query
  // feature is at least min_mean_log_likelihood. 3-view fleet scans,
  // right answers, score -1.1 (5 cm noise, median) to -2.3 (10 cm, worst
  // of 325); the floor of an unexplained feature is about -6; a small
  // object that fits inside a model's surface passes the inlier test but
  // not this one.
  float min_inlier_fraction = 0.25f;
  float min_mean_log_likelihood = -3.0f;
  // ... and leads the runner-up by at least this many times sqrt(features)
  // log-likelihood (BRAN, SRAN): eq. 7 sums n per-feature terms, so the lead
  // grows as n and its spread as sqrt(n) (a z-score; per feature it favoured
  // small scans, in total large ones). Most wrong answers are a look-alike
  // of the right one, which comes second a little behind. 0.8: on 85 draws
  // of 20 real cars (10 cm noise, 20 % occluded), 1.2 left right answers
  // among near-identical touring cars unflagged (81.0 % flagged with
  // ground, 88.8 % without) where 0.8 flags 86.8 / 92.8 % at 99.6 % right;
  // the fleet's wrong confident answers lead by more and stay the same.
  // The cost, 40 % occluded at 0.15 m (97.7-98.8 % right; 96.9 % at worst
  // at 1.2), full_coverage pays back: this margin does not know how much of
  // the vehicle the scan shows (results.md 11l; 1.3 until 9l, 1.2 until 11l) ...
  float min_margin = 0.8f;
  // ... times (full_coverage / stats.surface_coverage)^2 when the scan shows
  // less than this share of the first model's upward surface (0: never):
  // an occluder hides what tells near-identical models apart. On 6 x 1 440
  // scans of 20 real cars (0.05 / 0.15 m, 2-10 cm noise, 0 / 40 %
  // occlusion, with and without ground) the confident answers that were
  // wrong fell from 21 to 9 and the conditions under 99 % right from 3 to
  // 1, at 85.3 -> 82.7 % of the right answers flagged; on six seeds drawn
  // after, 19 -> 9 wrong. The fleet's flag 93.9 -> 92.0 %, the same 4
  // wrong; an exponent of 3 took it under 90 % (results.md 11m) ...
  float full_coverage = 0.9f;
  // ... and the scan pins the model's size: the query features, in the
  // model's frame under its pose, reach within max_extent_shortfall of both
  // ends of the model's box along x and along y and of its top, and lie at
  // most max_extent_overhang beyond them (the second outermost feature: one
  // stray feature is noise or a ground remnant; the bottom is not tested:
  // terrain removal cuts it). A scan that misses a vehicle's end is
  // explained as well by a longer look-alike, and a shortened one by a
  // shorter model (wrong answers name a longer model 4 times in 5). On the
  // 56-model fleet (3 x 896 queries, 16 conditions) these keep 99.2% of the
  // confident answers right and flag 75% of the right ones (a margin of 0.1
  // per feature alone: 95.5% / 76%).
  float max_extent_shortfall = 0.2f;  // m
  float max_extent_overhang = 0.3f;   // m
  // ... and its residuals are the scan's noise, not a shape: the
  // query features' signed distances to its surface, grouped by 0.5 m
  // surface cell, may spread between the cells' means at most this many
  // times as much as within the cells (an F statistic, about 1 for a right
  // model). A vehicle outside the database a few centimetres off its
  // nearest model leaves patches offset together. With 2.5, 99.6 % of the
  // fleet's confident answers are right and 91.1 % of its right answers
  // confident (99.3 % / 92.1 % without the test), and the scene tiles'
  // false alarms fall from 0.55 to 0.43 per tile (docs/results.md 9i).
  float max_residual_f = 2.5f;

  // Work budget (bounded time): whichever runs out first stops recognition.
  // BRAN's draws: a query whose leader the evidence settles stops long
  // before (stop_miss_probability), so this caps only the unsettled ones,
  // where the true model may not yet hold a good pose. 1 600 instead of
  // 800 costs the fleet's noisy scans 7.5 % more instructions (1 000
  // models, whose draws are extended: 22 %) and names 0.8-1.1 % more of
  // them right first; the focused search on such draws gained less at 71 %
  // more (docs/results.md 11n). The flight preset keeps 800.
  uint32_t max_trials = 1600;  // BRAN: doublet draws
  uint32_t sran_trials = 100;  // SRAN: doublet draws per model
  // Poses: BRAN's found for all models together (RecognitionStats::poses_found,
  // tilted ones too), SRAN's verified per model.
  uint32_t max_hypotheses = 6000;
  uint32_t max_pair_checks = 2000000;  // candidate pairs put through the cascade
  // BRAN: draws go on past max_trials (up to kTrialExtension x max_trials,
  // limits.hpp) while the draws found fewer poses than this (tilted ones
  // too, RecognitionStats::poses_found): in a database of many look-alikes
  // few draws pair up in one model (0: max_trials only, as the paper).
  uint32_t min_hypotheses = 200;

  // BRAN stops on evidence (RANSAC's termination bound): once the chance
  // that every draw so far missed an all-correct doublet of the leading
  // model, at its measured rate of correct candidates, is below this. 0:
  // run to the work budget (the paper's fixed number of trials).
  float stop_miss_probability = 0.01f;

  // Optional sensor position in input coordinates: normals are turned towards it.
  bool has_viewpoint = false;
  double viewpoint[3] = {0.0, 0.0, 0.0};
};

}  // namespace spinhash
