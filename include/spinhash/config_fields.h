/* The one list of spinhash's recognition settings and statistics.
 *
 * spinhash::RecognizerConfig and spinhash::RecognitionStats (config.hpp,
 * recognizer.hpp) are the C++ definitions, with each field's meaning and
 * default. Everything that mirrors them is produced from these lists: the C
 * structs of spinhash.h, the C <-> C++ bridge, the core's range check of a
 * configuration, the command-line flags, the JSON statistics, the
 * experiments' configuration text and the Python bindings.
 * tests/core/test_config_fields.cpp fails to compile when a C++ field is
 * missing here (or here and not in C++), or has another type.
 *
 * Config entries: X(kind, name, lo, hi, flag, help)
 *   kind  MODE (spinhash::Mode / int32_t), BOOL (bool / uint32_t 0 or 1),
 *         U32, U64, F32, VEC3D (double[3])
 *   lo hi the valid range (inclusive), checked by the core and the CLI
 *   flag  CLI11 option name(s) of `spinhash recognize`/`verify`, "" for
 *         none (a field set through another option says so in its help);
 *         BOOL flags set the field to false when given ("!--no-...")
 *
 * Stats entries: S(kind, name, member, json)
 *   kind  U32, U64 or BOOL; member is the C++ expression inside
 *   RecognitionStats; json the key in the CLI's "stats" object.
 *
 * Compiles as C99: no comment inside a list may use the // form (it would
 * swallow the line continuation). New fields are appended to the C structs'
 * ends only where the ABI promise demands; spinhash is 0.x, so the lists
 * keep the C++ order. */
#ifndef SPINHASH_CONFIG_FIELDS_H
#define SPINHASH_CONFIG_FIELDS_H

#define SPINHASH_CONFIG_FIELDS(X)                                                                            \
  X(MODE, mode, 0, 2, "--mode", "bran (batch RANSAC), sran (per-model RANSAC) or sind (LSH voting)")         \
  X(U64, seed, 0u, 0xFFFFFFFFFFFFFFFFull, "--seed", "sampling seed")                                         \
  X(U32, max_points, 1u, kMaxQueryPointsLimit, "--max-points",                                               \
    "largest cloud used (more: thinned or refused)")                                                         \
  X(BOOL, thin_large_clouds, 0, 1, "!--no-thin", "refuse a cloud above --max-points instead of thinning it") \
  X(U32, max_features, 2u, kMaxQueryFeaturesLimit, "--max-features", "query basis points kept")              \
  X(U32, max_models, 1u, kMaxModels, "--max-models", "models the workspace supports")                        \
  X(U32, max_spin_dims, 1u, kMaxSpinDims, "--max-spin-dims",                                                 \
    "largest spin image (bins) the workspace supports")                                                      \
  X(F32, query_basis_spacing, 0.0f, 100.0f, "--query-spacing",                                               \
    "query basis point spacing, m (0: the database's)")                                                      \
  X(F32, query_cloud_voxel, 0.0f, 100.0f, "--query-voxel",                                                   \
    "query density-equalising voxel, m (0: the database's)")                                                 \
  X(F32, ground_clearance, 0.0f, kMaxGroundClearance, "--ground-clearance",                                  \
    "m above the terrain (level or sloped, z up) dropped with it (0: keep the ground)")                      \
  X(U32, top_w, 1u, kMaxCandidates, "-W,--top-w", "W: candidates per query feature (BRAN)")                  \
  X(U32, top_w_sran, 1u, kMaxCandidates, "--top-w-sran", "W per model (SRAN)")                               \
  X(U32, top_w_sind, 1u, kMaxCandidates, "--top-w-sind", "W (SIND)")                                         \
  X(U32, max_bucket_scan, 1u, 1u << 24, "--max-bucket-scan", "LSH entries scanned per query feature")        \
  X(F32, d_min, 0.0f, 100.0f, "--d-min", "d_min of eq. 3, m")                                                \
  X(F32, theta_min_deg, 0.0f, 180.0f, "--theta-min", "theta_min of eq. 3, degrees")                          \
  X(F32, tol_distance, 0.0f, 100.0f, "--tol-distance", "doublet distance tolerance |d - d'|, m")             \
  X(F32, tol_angle_deg, 0.0f, 180.0f, "--tol-angle", "doublet angle tolerance, degrees")                     \
  X(F32, tol_handedness, 0.0f, 2.0f, "--tol-handedness",                                                     \
    "doublet handedness tolerance (rejects mirror images)")                                                  \
  X(F32, max_tilt_deg, 0.0f, 180.0f, "--max-tilt",                                                           \
    "largest tilt of a model's up axis from z a doublet's pose may have, degrees (180: any; z up)")          \
  X(F32, sigma, 1e-4f, 100.0f, "--sigma", "sigma of eq. 5, m")                                               \
  X(F32, sigma_surface, 1e-4f, 100.0f, "--sigma-surface",                                                    \
    "sigma of eq. 5 for the final point-to-surface residuals, m")                                            \
  X(F32, delta, 1e-4f, 100.0f, "--delta", "Delta of eq. 5, m")                                               \
  X(F32, delta_max, 1e-4f, 100.0f, "--delta-max", "Delta_max of eq. 5, m (at least Delta)")                  \
  X(F32, eta_max_deg, 0.0f, 180.0f, "--eta-max", "eta_max of eq. 6, degrees")                                \
  X(F32, spin_lambda, 1e-3f, 1e3f, "--spin-lambda", "p_s = exp(-L1 / lambda) of eq. 4")                      \
  X(U32, verify_features, 1u, kMaxQueryFeaturesLimit, "--verify-features",                                   \
    "query features scored per hypothesis")                                                                  \
  X(U32, transfer_models, 0u, kMaxTransferModels, "--transfer-models",                                       \
    "look-alikes each leading pose is also tried on (BRAN; 0: off, the paper's BRAN)")                       \
  X(U32, focus_models, 0u, kMaxFocusModels, "--focus-models",                                                \
    "BRAN: leading models given their own short RANSAC when the candidates are spread (0: off)")             \
  X(F32, lookalike_box_l1, 0.0f, 100.0f, "--lookalike-box",                                                  \
    "BRAN: on spread candidates a doublet may pair look-alikes whose boxes differ by at most this, m L1 "    \
    "(0: off)")                                                                                              \
  X(BOOL, refine_poses, 0, 1, "!--no-refine", "skip the least-squares pose refinement")                      \
  X(F32, min_inlier_fraction, 0.0f, 1.0f, "--min-inlier-fraction",                                           \
    "share of the query explained for a confident answer")                                                   \
  X(F32, min_mean_log_likelihood, -1e6f, 0.0f, "--min-mean-log-likelihood",                                  \
    "log-likelihood per query feature for a confident answer")                                               \
  X(F32, min_margin, 0.0f, 1e6f, "--min-margin",                                                             \
    "lead over the runner-up, log-likelihood / sqrt(query features), for a confident answer (BRAN, SRAN)")   \
  X(F32, full_coverage, 0.0f, 1.0f, "--full-coverage",                                                       \
    "surface_coverage below which the margin grows as (this / coverage)^2 (0: never)")                       \
  X(F32, max_extent_shortfall, 0.0f, 1e6f, "--max-extent-shortfall",                                         \
    "m of the model's box ends and top the scan may miss for a confident answer")                            \
  X(F32, max_extent_overhang, 0.0f, 1e6f, "--max-extent-overhang",                                           \
    "m the scan may reach beyond the model's box for a confident answer")                                    \
  X(F32, max_residual_f, 0.0f, 1e6f, "--max-residual-f",                                                     \
    "F of the residuals' means per surface cell against their scatter, for a confident answer")              \
  X(U32, max_trials, 0u, kMaxTrials, "--trials", "doublet draws (BRAN)")                                     \
  X(U32, sran_trials, 0u, 0xFFFFFFFFu, "--sran-trials", "doublet draws per model (SRAN)")                    \
  X(U32, max_hypotheses, 0u, 0xFFFFFFFFu, "--max-hypotheses",                                                \
    "poses found (BRAN total, tilted ones too; SRAN verified per model)")                                    \
  X(U32, max_pair_checks, 0u, 0xFFFFFFFFu, "--max-pair-checks", "candidate pairs through the cascade")       \
  X(U32, min_hypotheses, 0u, 0xFFFFFFFFu, "--min-hypotheses",                                                \
    "BRAN: draws past --trials (up to 4x) while they found fewer poses")                                     \
  X(F32, stop_miss_probability, 0.0f, 0.5f, "--stop-miss-probability",                                       \
    "BRAN stops once an all-correct doublet of the leader was missed with at most this chance (0: never)")   \
  X(BOOL, has_viewpoint, 0, 1, "", "set by --viewpoint")                                                     \
  X(VEC3D, viewpoint, 0, 0, "", "set by --viewpoint X Y Z: sensor position, normals turn towards it")

#define SPINHASH_STATS_FIELDS(S)                                                 \
  S(U32, points_in, extract.points_in, "points")                                 \
  S(U32, points_thinned, extract.points_thinned, "points_thinned")               \
  S(U32, points_nonfinite, extract.points_nonfinite, "points_nonfinite")         \
  S(U32, points_ground, extract.points_ground, "points_ground")                  \
  S(U32, points_equalised, extract.points_equalised, "points_equalised")         \
  S(U32, points_oriented, extract.points_oriented, "points_oriented")            \
  S(U32, basis_points, extract.basis_points, "basis_points")                     \
  S(BOOL, features_thinned, extract.features_thinned, "features_thinned")        \
  S(U32, features, features, "features")                                         \
  S(U32, salient_features, salient_features, "salient_features")                 \
  S(U64, candidates, candidates, "candidates")                                   \
  S(U64, bucket_entries, bucket_entries, "bucket_entries")                       \
  S(U32, trials, trials, "trials")                                               \
  S(U64, pair_checks, pair_checks, "doublets_tried")                             \
  S(U64, doublets_passed, doublets_passed, "doublets_passed")                    \
  S(U64, poses_tilted, poses_tilted, "poses_tilted")                             \
  S(U32, hypotheses, hypotheses, "hypotheses")                                   \
  S(U32, transferred, transferred, "transferred")                                \
  S(U32, refinements, refinements, "refinements")                                \
  S(BOOL, budget_exhausted, budget_exhausted, "budget_exhausted")                \
  S(BOOL, stopped_on_evidence, stopped_on_evidence, "stopped_on_evidence")       \
  S(BOOL, candidates_spread, candidates_spread, "candidates_spread")             \
  S(BOOL, bucket_scan_truncated, bucket_scan_truncated, "bucket_scan_truncated") \
  S(U64, workspace_used, workspace_used, "workspace_used")                       \
  S(F32, surface_coverage, surface_coverage, "surface_coverage")                 \
  S(F32, scan_density, scan_density, "scan_density")

/* C types of the kinds (spinhash.h). */
#define SPINHASH_CTYPE_MODE int32_t
#define SPINHASH_CTYPE_BOOL uint32_t
#define SPINHASH_CTYPE_U32 uint32_t
#define SPINHASH_CTYPE_U64 uint64_t
#define SPINHASH_CTYPE_F32 float
#define SPINHASH_CTYPE_VEC3D double
#define SPINHASH_CEXTENT_MODE
#define SPINHASH_CEXTENT_BOOL
#define SPINHASH_CEXTENT_U32
#define SPINHASH_CEXTENT_U64
#define SPINHASH_CEXTENT_F32
#define SPINHASH_CEXTENT_VEC3D [3]

#define SPINHASH_C_CONFIG_MEMBER(kind, name, lo, hi, flag, help) \
  SPINHASH_CTYPE_##kind name SPINHASH_CEXTENT_##kind;
#define SPINHASH_C_STATS_MEMBER(kind, name, member, json) SPINHASH_CTYPE_##kind name;

#endif /* SPINHASH_CONFIG_FIELDS_H */
