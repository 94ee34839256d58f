/* The recognizer's stages and the one list of each stage's parameters.
 *
 * Recognizer::run walks SPINHASH_STAGES in order (firmware-lib/recognize/
 * stages.cpp). Each stage's parameters are declared once, in
 * SPINHASH_PARAMS_<id>, and everything that mirrors them is produced from
 * these lists: the C++ structs with their defaults (spinhash::<Name>Params,
 * config.hpp), the C structs of spinhash.h, the C <-> C++ bridge, the core's
 * range check of a configuration, the command line (`--set stage.field=value`
 * and the flags), the experiments' configuration text and the Python
 * keywords and attributes. tests/core/test_config_fields.cpp checks the
 * mirrors; tests/host/test_field_mirrors.cpp checks docs/api.md's tables.
 *
 * Stages: S(id, Name, what) in run order; id names the member of
 * RecognizerConfig (and of RecognitionStats where the stage counts) and
 * the prefix of `--set`; Name the C++ struct, Name##Params.
 *
 * Parameters: X(kind, name, default, lo, hi, flag, why)
 *   kind     BOOL (bool / uint32_t 0 or 1), U32, F32
 *   default  the C++ default (a literal)
 *   lo hi    the valid range (inclusive; bounds from limits.hpp), checked by
 *            the core, the command line and Python; rules that join two
 *            fields are in recognize/config_check.cpp
 *   flag     CLI11 option name(s) of `spinhash recognize`, `verify` and
 *            `scene`, "" for none (`--set` reaches every field); BOOL flags
 *            set the field to false when given ("!--no-...")
 *   why      one line: what the value decides
 * A stage that can be skipped has `enabled` as its first field. A field's
 * name is unique across the stages but for `enabled`: Python names a
 * stage's fields by their own names and its switch <id>_enabled.
 *
 * Compiles as C99: no comment inside a list may use the // form (it would
 * swallow the line continuation). */
#ifndef SPINHASH_STAGE_FIELDS_H
#define SPINHASH_STAGE_FIELDS_H

#define SPINHASH_STAGES(S)                                                                                   \
  S(ground, Ground, "drops the terrain under the object and a band above it (z up)")                         \
  S(extract, Extract, "describes the object's points as oriented spin-image features")                       \
  S(candidates, Candidates, "finds each query feature's nearest model features (BRAN, SIND: the LSH index)") \
  S(carry, Carry, "verifies the cascade's first-pass leading poses on the full pass's features (BRAN)")      \
  S(draws, Draws, "draws doublets, poses them and verifies the poses (BRAN, SRAN)")                          \
  S(transfer, Transfer, "lends the leading poses to the look-alikes of their models (BRAN)")                 \
  S(focus, Focus, "gives the leading models a short RANSAC of their own on spread candidates (BRAN)")        \
  S(refine, Refine,                                                                                          \
    "rescores the leaders on every query feature, refines their poses, charges their unseen surface and "    \
    "lends the first pose to its look-alikes (BRAN, SRAN)")                                                  \
  S(rank, Rank, "orders the models, finds the look-alike group and orders twins by their residuals")         \
  S(confidence, Confidence, "decides whether the first model is named confidently")                          \
  S(classes, Classes, "ranks the vehicle classes and decides whether the first is named confidently")

#define SPINHASH_PARAMS_ground(X)                                                                           \
  X(BOOL, enabled, true, 0, 1, "", "drop the terrain under the object before its features are described")   \
  X(F32, ground_clearance, 0.25f, 0.0f, kMaxGroundClearance, "--ground-clearance",                          \
    "m above the terrain (level or sloped, z up) dropped with it, at most (0: keep the ground)")            \
  X(F32, clearance_sigmas, 4.5f, 0.0f, 100.0f, "",                                                          \
    "the band dropped above the terrain: this many sigma of the ground's measured roughness")               \
  X(F32, min_clearance, 0.05f, 0.0f, kMaxGroundClearance, "",                                               \
    "m: the band's least height (noise-free ground has no roughness)")                                      \
  X(F32, min_ground_cell, 0.5f, 0.05f, 10.0f, "",                                                           \
    "m: the terrain grid's finest cell (finer see too few ground points)")                                  \
  X(F32, max_ground_cell, 1.0f, 0.05f, 10.0f, "",                                                           \
    "m: the coarsest cell a sparse scan's terrain grid grows to")                                           \
  X(F32, min_points_per_cell, 25.0f, 0.0f, 1e6f, "",                                                        \
    "points per occupied cell below which the cells grow, so that edge cells still measure a spread")       \
  X(U32, fit_rounds, 5u, 1u, kMaxGroundFitRounds, "", "trimmed least-squares fits of the terrain plane")    \
  X(U32, coarse_rounds, 2u, 0u, kMaxGroundFitRounds, "",                                                    \
    "of those, the first ones, which trim only the cells rising by object_cell_rise")                       \
  X(F32, object_cell_rise, 0.5f, 0.0f, 100.0f, "",                                                          \
    "m: a cell whose lowest point rises more above the plane holds an object")                              \
  X(F32, ground_cell_rise, 0.2f, 0.0f, 100.0f, "",                                                          \
    "m: a cell whose lowest point rises at most this much is ground (noise, bumps)")                        \
  X(F32, roughness_band, 0.5f, 0.0f, 100.0f, "", "m above a ground cell's lowest point: its ground points") \
  X(U32, min_roughness_points, 5u, 1u, 0xFFFFFFFFu, "", "ground points a cell needs to measure its spread") \
  X(F32, clean_spread_factor, 2.0f, 0.0f, 100.0f, "",                                                       \
    "a ground cell spread more than this times the median holds an object")                                 \
  X(F32, spread_slack, 0.01f, 0.0f, 10.0f, "", "m added to that bound (noise-free ground has no spread)")   \
  X(F32, max_ground_roughness, 0.11f, 0.0f, 10.0f, "",                                                      \
    "m: rougher \"ground\" (its sigma) is an object's side, not terrain")                                   \
  X(F32, min_clean_border_share, 0.45f, 0.0f, 1.0f, "",                                                     \
    "share of the footprint's border cells that are clean ground: terrain reaches past the object")         \
  X(F32, below_terrain_sigmas, 4.0f, 0.0f, 100.0f, "",                                                      \
    "points deeper below the terrain than this many sigma (or min_below_terrain) say it is none ...")       \
  X(F32, min_below_terrain, 0.3f, 0.0f, 100.0f, "", "m: ... at least this deep ...")                        \
  X(F32, max_below_terrain_share, 0.02f, 0.0f, 1.0f, "",                                                    \
    "... when more than this share of the points lie there")                                                \
  X(F32, max_ground_slope, 0.3249197f, 0.0f, 100.0f, "",                                                    \
    "rise per m: steeper \"ground\" (0.3249197: 18 degrees) is a vehicle's side or cargo bed")              \
  X(F32, min_object_ground_share, 0.15f, 0.0f, 1.0f, "",                                                    \
    "share of the points within the band that says there is ground under the object")                       \
  X(F32, min_ground_cell_share, 0.3f, 0.0f, 1.0f, "",                                                       \
    "share of the occupied cells that are ground, likewise")                                                \
  X(U32, min_sparse_ground_cells, 24u, 0u, kObjectGroundCells, "",                                          \
    "clean ground cells that prove terrain under a sparse scan (a bare vehicle's roof shows fewer)")        \
  X(U32, min_ringed_ground_cells, 12u, 0u, kObjectGroundCells, "",                                          \
    "fewer, down to this many, prove it when they ring the footprint under a body")                         \
  X(F32, min_ringed_border_share, 0.9f, 0.0f, 1.0f, "", "share of the border cells clean for that")         \
  X(F32, min_body_rise, 1.0f, 0.0f, 100.0f, "",                                                             \
    "m above the terrain the highest point reaches for that: a vehicle stands there")                       \
  X(F32, min_dense_ground_area, 10.0f, 0.0f, 1e6f, "",                                                      \
    "m^2 of clean ground cells that prove terrain under a dense scan (a low car's bodywork shows less)")    \
  X(F32, body_above, 0.3f, 0.0f, 100.0f, "",                                                                \
    "m above the band: a column rising this high holds a body, whose lower sides in the band stay")         \
  X(F32, band_kept_from, 0.7f, 0.0f, 1.0f, "",                                                              \
    "share of the band's height from which band points under a body stay (below: ground)")

#define SPINHASH_PARAMS_extract(X)                                                                           \
  X(F32, query_basis_spacing, 0.0f, 0.0f, 100.0f, "--query-spacing",                                         \
    "query basis point spacing, m (0: the database's)")                                                      \
  X(F32, query_cloud_voxel, 0.0f, 0.0f, 100.0f, "--query-voxel",                                             \
    "query density-equalising voxel, m (0: the database's; coarser: fewer instructions, answers move)")      \
  X(F32, min_oriented_share, 0.9f, 0.0f, 1.0f, "",                                                           \
    "share of the points that must get a normal; fewer (a sparse scan): the normal radius grows")            \
  X(F32, normal_radius_growth, 1.5f, 1.0f, 10.0f, "", "factor the normal radius grows by for a sparse scan") \
  X(U32, max_radius_steps, 2u, 0u, kMaxNormalRadiusSteps, "", "times the normal radius grows at most")

#define SPINHASH_PARAMS_candidates(X)                                                                        \
  X(U32, top_w, 50u, 1u, kMaxCandidates, "-W,--top-w", "W: candidates per query feature (BRAN)")             \
  X(U32, top_w_sran, 5u, 1u, kMaxCandidates, "--top-w-sran", "W per model (SRAN, and the focused search)")   \
  X(U32, top_w_sind, 1u, 1u, kMaxCandidates, "--top-w-sind", "W (SIND)")                                     \
  X(U32, max_bucket_scan, 1024u, 1u, kMaxBucketScan, "--max-bucket-scan",                                    \
    "LSH entries scanned per query feature")                                                                 \
  X(F32, spread_perplexity, 25.0f, 1.0f, 1e6f, "",                                                           \
    "models a feature's candidates name on average (perplexity) above which they are spread over "           \
    "look-alikes")                                                                                           \
  X(F32, sparse_density, 50.0f, 0.0f, 1e6f, "",                                                              \
    "object points per m^2 of the query's footprint below which it is searched as a sparse scan (0: never)") \
  X(U32, sparse_scan_scale, 4u, 1u, kMaxSparseScale, "",                                                     \
    "a sparse scan's lookups scan this many times max_bucket_scan entries (crowded buckets) ...")            \
  X(U32, max_sparse_bucket_scan, 4096u, 1u, kMaxBucketScan, "",                                              \
    "... up to this many; the query's total stays max_features x max_bucket_scan")

#define SPINHASH_PARAMS_carry(X)                                                                             \
  X(BOOL, enabled, false, 0, 1, "",                                                                          \
    "carry the first pass's leading poses into the full pass (the cascade; off: carried poses let a "        \
    "look-alike outrank the model the full pass's own draws find, without them an escalated query gets the " \
    "full pass alone's answer)")                                                                             \
  X(U32, carry_models, 8u, 0u, kMaxCarriedPoses, "",                                                         \
    "leading models of the first pass whose poses the full pass verifies first")

#define SPINHASH_PARAMS_draws(X)                                                                             \
  X(F32, d_min, 0.5f, 0.0f, 100.0f, "--d-min", "d_min of eq. 3, m")                                          \
  X(F32, theta_min_deg, 10.0f, 0.0f, 180.0f, "--theta-min", "theta_min of eq. 3, degrees")                   \
  X(F32, tol_distance, 0.30f, 0.0f, 100.0f, "--tol-distance",                                                \
    "doublet distance tolerance: d and d' may differ by this, m")                                            \
  X(F32, tol_angle_deg, 25.0f, 0.0f, 180.0f, "--tol-angle", "doublet angle tolerance, degrees")              \
  X(F32, tol_handedness, 0.5f, 0.0f, 2.0f, "--tol-handedness",                                               \
    "doublet handedness tolerance (rejects mirror images)")                                                  \
  X(F32, max_tilt_deg, 45.0f, 0.0f, 180.0f, "--max-tilt",                                                    \
    "largest tilt of a model's up axis from z a doublet's pose may have, degrees (180: any; z up)")          \
  X(F32, normal_lever, 1.0f, 1e-3f, 100.0f, "",                                                              \
    "m: a doublet's pose weighs a normal's error of e radians as e times this of position")                  \
  X(F32, sigma, 0.15f, 1e-4f, 100.0f, "--sigma",                                                             \
    "sigma of eq. 5, m: sensor noise plus basis-point sampling")                                             \
  X(F32, delta, 0.30f, 1e-4f, 100.0f, "--delta", "Delta of eq. 5, m: the inlier radius")                     \
  X(F32, delta_max, 0.60f, 1e-4f, 100.0f, "--delta-max", "Delta_max of eq. 5, m (at least Delta)")           \
  X(F32, eta_max_deg, 35.0f, 0.0f, 180.0f, "--eta-max", "eta_max of eq. 6, degrees")                         \
  X(F32, spin_lambda, 0.5f, 1e-3f, 1e3f, "--spin-lambda", "p_s = exp(-L1 / lambda) of eq. 4")                \
  X(U32, verify_features, 256u, 1u, kMaxQueryFeaturesLimit, "--verify-features",                             \
    "query features scored per hypothesis (evenly spread; the leaders are rescored on all)")                 \
  X(U32, preemptive_first, 32u, 0u, kMaxQueryFeaturesLimit, "",                                              \
    "features after which a pose is dropped when its mean term lies preemptive_first_slack below the "       \
    "best's")                                                                                                \
  X(F32, preemptive_first_slack, 1.5f, 0.0f, 1e6f, "", "log units per feature of that first check")          \
  X(U32, preemptive_second, 96u, 0u, kMaxQueryFeaturesLimit, "", "features of the second, steadier check")   \
  X(F32, preemptive_second_slack, 0.8f, 0.0f, 1e6f, "", "log units per feature of the second check")         \
  X(U32, max_trials, 1600u, 0u, kMaxTrials, "--trials", "doublet draws (BRAN)")                              \
  X(U32, sran_trials, 100u, 0u, 0xFFFFFFFFu, "--sran-trials", "doublet draws per model (SRAN)")              \
  X(U32, max_hypotheses, 6000u, 0u, 0xFFFFFFFFu, "--max-hypotheses",                                         \
    "poses found (BRAN total, tilted ones too; SRAN verified per model)")                                    \
  X(U32, max_pair_checks, 2000000u, 0u, 0xFFFFFFFFu, "--max-pair-checks",                                    \
    "candidate pairs through the cascade")                                                                   \
  X(U32, min_hypotheses, 200u, 0u, 0xFFFFFFFFu, "--min-hypotheses",                                          \
    "BRAN: draws past --trials (up to 4x) while they found fewer poses")                                     \
  X(U32, sparse_trial_scale, 4u, 1u, kMaxSparseScale, "",                                                    \
    "a sparse scan's draws: this many times max_trials and min_hypotheses (its features are few and noisy)") \
  X(F32, stop_miss_probability, 0.01f, 0.0f, 0.5f, "--stop-miss-probability",                                \
    "BRAN stops once an all-correct doublet of the leader was missed with at most this chance (0: never)")   \
  X(U32, min_evidence_draws, 64u, 0u, kMaxTrials, "",                                                        \
    "draws before the stop on evidence is consulted (the first correct doublets give poses degrees off)")    \
  X(F32, lookalike_box_l1, 0.6f, 0.0f, 100.0f, "--lookalike-box",                                            \
    "BRAN: on spread candidates a doublet may pair look-alikes whose boxes differ by at most this, m L1 "    \
    "(0: off)")                                                                                              \
  X(U32, lookalike_pairs_per_candidate, 1u, 0u, kMaxCandidates, "",                                          \
    "look-alike partners of one candidate through the cascade (the nearest: further ones repeat its pose)")  \
  X(U32, lookalike_pairs_per_draw, 4u, 0u, 0xFFFFFFFFu, "",                                                  \
    "look-alike pairs through the cascade per draw (among identical copies every candidate has a partner)")

#define SPINHASH_PARAMS_transfer(X)                                                               \
  X(BOOL, enabled, true, 0, 1, "",                                                                \
    "lend the leading poses to look-alikes, here and after refinement (false: the paper's BRAN)") \
  X(U32, transfer_models, 32u, 0u, kMaxTransferModels, "--transfer-models",                       \
    "look-alikes each leading pose is also tried on (BRAN; 0: none)")                             \
  X(U32, transfer_poses, 4u, 0u, kMaxTransferPoses, "", "leading models whose poses are lent")

#define SPINHASH_PARAMS_focus(X)                                                                        \
  X(BOOL, enabled, true, 0, 1, "",                                                                      \
    "search the leading models on their own when the candidates are spread or the draws were extended") \
  X(U32, focus_models, 16u, 0u, kMaxFocusModels, "--focus-models",                                      \
    "BRAN: leading models given their own short RANSAC when the candidates are spread (0: none)")       \
  X(U32, focus_trials, 100u, 0u, kMaxTrials, "", "draws each focused model gets (SRAN's per model)")

#define SPINHASH_PARAMS_refine(X)                                                                            \
  X(BOOL, refine_poses, true, 0, 1, "!--no-refine",                                                          \
    "refine the leaders' poses by least squares (false: they are rescored as found)")                        \
  X(F32, sigma_surface, 0.10f, 1e-4f, 100.0f, "--sigma-surface",                                             \
    "sigma of eq. 5 for the final point-to-surface residuals, m")                                            \
  X(F32, patch_radius_per_spacing, 0.5f, 0.0f, 10.0f, "",                                                    \
    "a model feature stands for the surface this share of the basis spacing around it")                      \
  X(U32, rescored_models, 8u, 0u, kMaxRescoredModels, "",                                                    \
    "leading models rescored on every query feature (and refined)")                                          \
  X(U32, refine_iterations, 3u, 0u, kMaxRefineIterations, "",                                                \
    "least-squares steps per pose while they raise its score")                                               \
  X(F32, refine_window, 0.5f, 0.0f, 1e6f, "",                                                                \
    "log-likelihood per feature below the best beyond which a rescored model is not refined (a wrong "       \
    "model)")                                                                                                \
  X(F32, turn_screen_slack, 0.3f, 0.0f, 1e6f, "",                                                            \
    "the pose turned end to end is refined too when it scores at most this much per feature below")          \
  X(F32, damping_per_match, 1e-3f, 0.0f, 1.0f, "",                                                           \
    "damping of the least squares per match: a direction no match constrains does not move")                 \
  X(F32, upward_normal_z, 0.7071f, 0.0f, 1.0f, "",                                                           \
    "a posed model feature faces the sensor above when its normal's z is at least this")                     \
  X(F32, log_seen, -0.35667f, -100.0f, 0.0f, "",                                                             \
    "log p of an upward model patch with a query feature within Delta (a patch is missed 30 % of the time)") \
  X(F32, log_missed, -1.20397f, -100.0f, 0.0f, "", "log p of one without (occlusion, dark or wet surfaces)") \
  X(U32, lend_spread_models, 16u, 0u, kMaxLendModels, "",                                                    \
    "look-alikes the first pose is lent to as it is when the candidates are spread")                         \
  X(U32, lend_family_models, 8u, 0u, kMaxLendModels, "",                                                     \
    "siblings nearest by box it is lent to otherwise, end-aligned and turned")                               \
  X(U32, lend_rounds, 2u, 0u, kMaxLendRounds, "", "lendings from each new first model")                      \
  X(F32, lend_spread_window, 0.6f, 0.0f, 1e6f, "",                                                           \
    "log units per feature: a pose lent as it is is finalised within this of the first's")                   \
  X(F32, lend_end_aligned_window, 0.3f, 0.0f, 1e6f, "",                                                      \
    "log units per feature: an end-aligned pose is finalised within this of the first's")                    \
  X(F32, lend_min_end_shift, 0.05f, 0.0f, 100.0f, "",                                                        \
    "m: a front-aligned pose this close to the rear-aligned one is the same pose")

#define SPINHASH_PARAMS_rank(X)                                                     \
  X(BOOL, twins_by_residuals, true, 0, 1, "",                                       \
    "within a look-alike group the model whose residuals are noise comes first")    \
  X(F32, residual_cell, 0.5f, 0.01f, 100.0f, "",                                    \
    "m: the model-surface cells whose residuals share one offset (the residual F)") \
  X(U32, residual_min_cell_features, 4u, 2u, kMaxQueryFeaturesLimit, "",            \
    "query features a cell needs to count in the residual F")

#define SPINHASH_PARAMS_confidence(X)                                                                        \
  X(F32, min_inlier_fraction, 0.25f, 0.0f, 1.0f, "--min-inlier-fraction",                                    \
    "share of the query explained for a confident answer")                                                   \
  X(F32, min_mean_log_likelihood, -3.0f, -1e6f, 0.0f, "--min-mean-log-likelihood",                           \
    "log-likelihood per query feature for a confident answer")                                               \
  X(F32, min_margin, 0.8f, 0.0f, 1e6f, "--min-margin",                                                       \
    "lead over the runner-up, log-likelihood / sqrt(query features), for a confident answer (BRAN, SRAN)")   \
  X(F32, spread_margin_factor, 2.0f, 0.0f, 100.0f, "",                                                       \
    "the margin's factor on spread candidates: the best of many near-identical scores leads by chance")      \
  X(F32, full_coverage, 0.9f, 0.0f, 1.0f, "--full-coverage",                                                 \
    "surface_coverage below which the margin grows as (this / coverage)^2 (0: never)")                       \
  X(F32, full_model_density, 130.0f, 0.0f, 1e6f, "",                                                         \
    "scan density (points per m^2 of the model top seen) below which the margin grows as 1 / sqrt(density)") \
  X(F32, min_model_density, 50.0f, 0.0f, 1e6f, "", "scan density below which no model is named confidently") \
  X(F32, max_extent_shortfall, 0.2f, 0.0f, 1e6f, "--max-extent-shortfall",                                   \
    "m of the model's box ends and top the scan may miss for a confident answer")                            \
  X(F32, max_extent_overhang, 0.3f, 0.0f, 1e6f, "--max-extent-overhang",                                     \
    "m the scan may reach beyond the model's box for a confident answer")                                    \
  X(F32, max_residual_f, 2.5f, 0.0f, 1e6f, "--max-residual-f",                                               \
    "F of the residuals' means per surface cell against their scatter, for a confident answer")              \
  X(F32, spread_residual_factor, 0.8f, 0.0f, 100.0f, "",                                                     \
    "max_residual_f's factor on spread candidates: a look-alike differs from the first by one patch")

#define SPINHASH_PARAMS_classes(X)                                                                           \
  X(U32, min_class_features, 12u, 0u, kMaxQueryFeaturesLimit, "", "query features a confident class needs")  \
  X(F32, min_class_density, 5.0f, 0.0f, 1e6f, "", "scan density a confident class needs")                    \
  X(F32, class_extent_factor, 2.0f, 0.0f, 100.0f, "",                                                        \
    "the scan may miss or overhang the class leader's box this many times max_extent_shortfall / _overhang") \
  X(U32, group_fit_models, 8u, 1u, kMaxGroupFitModels, "",                                                   \
    "posed models of the first group tried in ranking order for one whose box the scan fits (group level)")  \
  X(F32, min_height_density, 50.0f, 0.0f, 1e6f, "",                                                          \
    "without terrain, scan density below which the scan's height is not measured (coarser than a class "     \
    "step)")                                                                                                 \
  X(F32, top_noise_sigmas, 3.0f, 0.0f, 100.0f, "",                                                           \
    "a noisy roof's highest points lie this many sigma of the noise above it")                               \
  X(F32, model_bottom_gap, 0.2f, 0.0f, 100.0f, "",                                                           \
    "m a vehicle's top above the terrain may exceed its model box's height (its wheels' unseen bottom)")     \
  X(F32, top_sampling_slack, 0.1f, 0.0f, 100.0f, "",                                                         \
    "m below the roof's top a sparse scan's second highest point may lie")                                   \
  X(F32, bottom_gap_spacings, 3.0f, 0.0f, 100.0f, "",                                                        \
    "without terrain, the scan's lowest features lie at most this many point spacings above the box bottom")

/* C types of the kinds (spinhash.h); the config's top-level kinds are in config_fields.h. */
#define SPINHASH_C_PARAMS_MEMBER(kind, name, def, lo, hi, flag, why) SPINHASH_CTYPE_##kind name;

#endif /* SPINHASH_STAGE_FIELDS_H */
