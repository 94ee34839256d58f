/* The one list of spinhash's top-level recognition settings (the mode, the
 * seed, the capacities that size the workspace and the viewpoint) and of its
 * statistics. The stages' parameters are in stage_fields.h.
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
 *   kind  U32, U64, BOOL or F32; name the member of the C struct
 *   spinhash_stats; member the C++ expression inside RecognitionStats (its
 *   stage's block); json the key in the CLI's "stats" object.
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
  X(BOOL, has_viewpoint, 0, 1, "", "set by --viewpoint")                                                     \
  X(VEC3D, viewpoint, 0, 0, "", "set by --viewpoint X Y Z: sensor position, normals turn towards it")        \
  X(BOOL, cascade, 0, 1, "!--no-cascade",                                                                    \
    "the full pass alone, without the cascade's first pass at the first_* settings (which ends a query "     \
    "when confident or by the agree table)")                                                                 \
  X(F32, first_query_voxel, 0.0f, 100.0f, "--first-voxel",                                                   \
    "the first pass's query voxel, m (0: the database's)")                                                   \
  X(U32, first_features, 2u, kMaxQueryFeaturesLimit, "--first-features",                                     \
    "the first pass's query features (at most max_features)")                                                \
  X(U32, first_bucket_scan, 1u, kMaxBucketScan, "--first-bucket-scan",                                       \
    "the first pass's LSH entries scanned per feature (at most max_bucket_scan)")                            \
  X(U32, first_top_w, 1u, kMaxCandidates, "--first-top-w",                                                   \
    "the first pass's candidates per feature (at most top_w)")                                               \
  X(U32, first_verify_features, 1u, kMaxQueryFeaturesLimit, "--first-verify-features",                       \
    "the first pass's features per hypothesis")                                                              \
  X(U32, first_trials, 0u, kMaxTrials, "--first-trials", "the first pass's doublet draws (BRAN)")            \
  X(F32, first_min_margin, 0.0f, 1e6f, "--first-min-margin",                                                 \
    "the first pass's confidence margin: stricter than the full pass's, since its answer ends the query")    \
  X(U64, max_work, 1u, kMaxQueryWork, "--max-work",                                                          \
    "work units a query may spend over both passes (work_meter.hpp); reached: the best answer so far, "      \
    "status work_cap_reached")

#define SPINHASH_STATS_FIELDS(S)                                                            \
  S(U32, points_in, extract.points_in, "points")                                            \
  S(U32, points_thinned, extract.points_thinned, "points_thinned")                          \
  S(U32, points_nonfinite, extract.points_nonfinite, "points_nonfinite")                    \
  S(U32, points_ground, ground.points_ground, "points_ground")                              \
  S(U32, points_equalised, extract.points_equalised, "points_equalised")                    \
  S(U32, points_oriented, extract.points_oriented, "points_oriented")                       \
  S(U32, basis_points, extract.basis_points, "basis_points")                                \
  S(BOOL, features_thinned, extract.features_thinned, "features_thinned")                   \
  S(U32, features, extract.features, "features")                                            \
  S(U32, salient_features, candidates.salient_features, "salient_features")                 \
  S(U64, candidates, candidates.kept, "candidates")                                         \
  S(U64, bucket_entries, candidates.bucket_entries, "bucket_entries")                       \
  S(U32, trials, draws.trials, "trials")                                                    \
  S(U64, pair_checks, draws.pair_checks, "doublets_tried")                                  \
  S(U64, doublets_passed, draws.doublets_passed, "doublets_passed")                         \
  S(U64, poses_tilted, draws.poses_tilted, "poses_tilted")                                  \
  S(U32, hypotheses, draws.hypotheses, "hypotheses")                                        \
  S(U32, transferred, transfer.transferred, "transferred")                                  \
  S(U32, refinements, refine.refinements, "refinements")                                    \
  S(U32, rescores, refine.rescores, "rescores")                                             \
  S(U32, screens, refine.screens, "screens")                                                \
  S(BOOL, budget_exhausted, draws.budget_exhausted, "budget_exhausted")                     \
  S(BOOL, stopped_on_evidence, draws.stopped_on_evidence, "stopped_on_evidence")            \
  S(BOOL, candidates_spread, candidates.spread, "candidates_spread")                        \
  S(BOOL, bucket_scan_truncated, candidates.bucket_scan_truncated, "bucket_scan_truncated") \
  S(U64, workspace_used, workspace_used, "workspace_used")                                  \
  S(F32, surface_coverage, confidence.surface_coverage, "surface_coverage")                 \
  S(F32, scan_density, confidence.scan_density, "scan_density")                             \
  S(U32, carried, carry.carried, "carried")                                                 \
  S(U32, passes, cascade.passes, "passes")                                                  \
  S(U32, answered_by, cascade.answered_by, "answered_by")                                   \
  S(BOOL, stopped_on_agreement, cascade.stopped_on_agreement, "stopped_on_agreement")       \
  S(U64, first_pass_work, cascade.first_work, "first_pass_work")                            \
  S(U64, full_pass_work, cascade.full_work, "full_pass_work")                               \
  S(U64, work, cascade.work, "work")                                                        \
  S(BOOL, work_capped, cascade.work_capped, "work_capped")

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
