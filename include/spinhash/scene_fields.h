/* The one list of the scene's settings, statistics and output keys.
 *
 * spinhash::SceneConfig, SceneStats (scene.hpp), StreamConfig and
 * StreamStats (scene_stream.hpp) are the C++ definitions, with each field's
 * meaning and default. What mirrors them is produced from these lists: the
 * core's range check of a configuration (firmware-lib/scene/scene_config.cpp),
 * the command-line flags of `spinhash scene` and `survey`
 * (host-tools/pipeline/scene_flags.*), the Python keywords, properties and
 * statistics dicts (python/src/py_scene*.cpp). tests/core/test_config_fields.cpp
 * fails to compile when a C++ field is missing here (or here and not in C++)
 * or has another type; tests/host/test_field_mirrors.cpp checks the flags
 * against --help and docs/cli.md, the fields and defaults against the tables
 * of docs/api.md, and the object's keys against `scene`'s JSON lines.
 *
 * Config entries: X(kind, name, lo, hi, flag, help)
 *   kind  U32, F32, BOOL, VEC3D (double[3]); the nested configs
 *         (SceneConfig::recognizer: config_fields.h; StreamConfig::scene:
 *         this list) are not entries
 *   lo hi the valid range (inclusive; bounds from limits.hpp), checked by
 *         the core, the CLI and Python; rules that join two fields are in
 *         scene_config.cpp
 *   flag  the option of `spinhash scene` (and `survey` where it takes it),
 *         "" for none
 *
 * Stats entries: S(kind, name, key)
 *   kind  U32, U64, SIZE (size_t), F64, KINDS (uint32_t[kObjectKinds], one
 *         count per object kind, a dict by kind name), SCENE (the nested
 *         SceneStats)
 *   key   the key in Python's statistics dicts
 *
 * Object keys: K(key, attribute): the members of a scene object in `scene`'s
 * JSON line, in order (host-tools/pipeline/object_json.hpp), and the
 * attribute of Python's SceneObject that holds each ("" for the line's
 * context: the tile and the object's number).
 *
 * Compiles as C99: no comment inside a list may use the // form (it would
 * swallow the line continuation). */
#ifndef SPINHASH_SCENE_FIELDS_H
#define SPINHASH_SCENE_FIELDS_H

#define SPINHASH_SCENE_CONFIG_FIELDS(X)                                                                     \
  X(U32, top_n, 1u, kMaxSceneTopN, "--top", "models listed per object")                                     \
  X(F32, window_core, kMinWindowCore, kMaxWindowEdge, "--window-core",                                      \
    "m: the windows' owned squares (a multiple of the grid cells, 0.5 m)")                                  \
  X(F32, window_margin, 0.0f, kMaxWindowEdge, "--window-margin",                                            \
    "m of terrain seen beyond a window's core: half the longest vehicle plus the terrain filter's reach")   \
  X(F32, object_margin, 0.0f, kMaxWindowEdge, "--object-margin",                                            \
    "m of points a window segments beyond its core: half the largest vehicle's diagonal, at most the "      \
    "margin")                                                                                               \
  X(U32, max_tile_points, 1u, kMaxSceneTilePoints, "--max-window-points",                                   \
    "points a scene window holds (default: sized from the tile's density; more: counted, not answered)")    \
  X(U32, max_objects, 1u, kMaxSceneObjects, "--max-objects",                                                \
    "objects per tile (more: the rest are not recognised)")                                                 \
  X(U64, window_max_work, 0u, kMaxQueryWork, "--window-max-work",                                           \
    "work units a window's recognitions share (0: each object's --max-work alone); once spent, the "        \
    "window's other candidates are not recognised")                                                         \
  X(U32, max_terrain_cells, 1u, kMaxSceneGridCells, "",                                                     \
    "terrain grid cells, shared by the windows of a row side by side")                                      \
  X(U32, max_segment_cells, 1u, kMaxSceneGridCells, "", "segmentation grid cells per window")               \
  X(F32, terrain_cell, kMinSceneTerrainCell, kMaxSceneTerrainCell, "", "m: terrain grid cell")              \
  X(F32, terrain_window, kMinSceneTerrainCell, kMaxTerrainWindow, "",                                       \
    "m: the terrain filter's widest opening (at least terrain_cell)")                                       \
  X(F32, terrain_slope, 0.0f, kMaxTerrainSlope, "", "rise per m between the terrain filter's windows")      \
  X(F32, terrain_dh0, 0.0f, kMaxTerrainDh, "", "m: the terrain filter's first height threshold")            \
  X(F32, terrain_dh_max, 0.0f, kMaxTerrainDh, "", "m: its largest height threshold (at least terrain_dh0)") \
  X(F32, ground_height, 0.0f, kMaxGroundHeight, "", "m above the terrain that is still ground")             \
  X(F32, terrain_low_band, 0.0f, kMaxTerrainDh, "",                                                         \
    "m: a terrain cell's value is the mean of its points this close to its lowest")                         \
  X(F32, terrain_noise_gap, 0.0f, kMaxTerrainDh, "--terrain-noise-gap",                                     \
    "m (0: off): a cell's lowest point this far under its next and under the cells around is low noise")    \
  X(F32, terrain_noise_reach, 0.0f, kMaxTerrainNoiseReach, "",                                              \
    "m: the cells around that a low-noise test compares with")                                              \
  X(U32, terrain_noise_support, 1u, kMaxTerrainNoiseSupport, "",                                            \
    "cells around, as low within the gap, that keep a cell's lowest (or a quarter of them, if fewer)")      \
  X(F32, segment_cell, kMinSegmentCell, kMaxSegmentCell, "--segment-cell",                                  \
    "m: segmentation grid cell (the tile path doubles it up to a tile's point spacing, twice at most)")     \
  X(F32, layer_split_height, kSmallestPositive, kMaxSceneGate, "",                                          \
    "m above the terrain: the low layer (vehicles) below, the high layer (crowns, roofs) above")            \
  X(U32, min_object_points, 1u, 0xFFFFFFFFu, "", "smaller components are fragments, not objects")           \
  X(F32, column_bin, kMinColumnBin, kMaxColumnBin, "", "m: height bins of a segmentation cell's column")    \
  X(F32, layer_gap, kMinColumnBin, kMaxSceneGate, "",                                                       \
    "m: an empty gap this tall in a cell's column parts the low layer from what is above (a multiple of "   \
    "column_bin)")                                                                                          \
  X(F32, min_length, 0.0f, kMaxSceneGate, "", "m: shorter is too small")                                    \
  X(F32, max_length, 0.0f, kMaxSceneGate, "", "m: longer is too large (at least min_length)")               \
  X(F32, min_width, 0.0f, kMaxSceneGate, "", "m: narrower is not vehicle-shaped (a wall)")                  \
  X(F32, max_width, 0.0f, kMaxSceneGate, "", "m: wider is too large (at least min_width)")                  \
  X(F32, min_height, 0.0f, kMaxSceneGate, "", "m above the terrain: lower is too small")                    \
  X(F32, max_height, 0.0f, kMaxSceneGate, "", "m above the terrain: taller is not vehicle-shaped")          \
  X(F32, max_clearance, 0.0f, kMaxSceneGate, "",                                                            \
    "m: a lowest point higher above the terrain floats (a crown)")                                          \
  X(F32, max_size_mismatch, 0.0f, kMaxSizeMismatch, "",                                                     \
    "share of the best model's length and width the object may differ by, for a confident answer")          \
  X(F32, class_size_factor, 0.0f, kMaxSizeMismatch, "",                                                     \
    "times max_size_mismatch the class leader's length and width may differ by, for a confident class")     \
  X(F32, max_ground_sink, 0.0f, kNoUpperBound, "",                                                          \
    "m the best model may sink into the terrain under its pose, for a confident answer")                    \
  X(U32, band_columns, 1u, kMaxBandColumns, "", "window columns a tile streams side by side across")        \
  X(F32, row_depth, kSmallestPositive, kMaxStreamExtent, "",                                                \
    "m along x: a tile is pushed row by row (its points in any order within a row)")

#define SPINHASH_STREAM_CONFIG_FIELDS(X)                                                                 \
  X(BOOL, origin_given, 0, 1, "", "set by origin")                                                       \
  X(VEC3D, origin, 0, 0, "", "x y z of the frame's origin (else the first finite point pushed)")         \
  X(F32, heading_deg, -360.0f, 360.0f, "", "along-track direction, degrees from +x (90: north)")         \
  X(F32, swath_min, -kMaxStreamExtent, kMaxStreamExtent, "", "m across track: points below are dropped") \
  X(F32, swath_max, -kMaxStreamExtent, kMaxStreamExtent, "", "m across track: points above are dropped") \
  X(F32, own_min, -kMaxStreamExtent, kMaxStreamExtent, "", "m across track: the owned band's start")     \
  X(F32, own_max, -kMaxStreamExtent, kMaxStreamExtent, "", "m across track: the owned band's end")       \
  X(F32, max_lag, 0.0f, kMaxStreamExtent, "", "m a point may lag behind the furthest along track")       \
  X(F32, max_jump, kSmallestPositive, kMaxStreamExtent, "", "m ahead beyond which a point is a glitch")  \
  X(U32, jump_confirm_points, 1u, kMaxJumpConfirmPoints, "",                                             \
    "points that must agree before a jump past max_jump is a gap in the data, not a glitch")             \
  X(F32, max_z_offset, kSmallestPositive, kMaxStreamExtent, "",                                          \
    "m from the origin's z beyond which a "                                                              \
    "point is an outlier")                                                                               \
  X(U32, max_buffered_points, 1u, kMaxStreamBufferedPoints, "", "points held awaiting their windows")

#define SPINHASH_SCENE_STATS_FIELDS(S)                     \
  S(U32, points_in, "points")                              \
  S(U32, points_nonfinite, "points_nonfinite")             \
  S(U32, points_ground, "points_ground")                   \
  S(U32, points_in_objects, "points_in_objects")           \
  S(U32, points_fragments, "points_fragments")             \
  S(U32, points_low_noise, "points_low_noise")             \
  S(U32, terrain_cells, "terrain_cells")                   \
  S(U32, terrain_windows, "terrain_windows")               \
  S(U32, segment_cells, "segment_cells")                   \
  S(U32, components, "components")                         \
  S(U32, objects_dropped, "objects_dropped")               \
  S(KINDS, objects_by_kind, "objects_by_kind")             \
  S(U32, windows, "windows")                               \
  S(U32, windows_overflowed, "windows_overflowed")         \
  S(U64, recognition_hypotheses, "recognition_hypotheses") \
  S(U64, recognition_candidates, "recognition_candidates") \
  S(U64, recognition_work, "recognition_work")             \
  S(U32, objects_out_of_work, "objects_out_of_work")       \
  S(SIZE, workspace_used, "workspace_used")

#define SPINHASH_STREAM_STATS_FIELDS(S)                \
  S(SCENE, scene, "scene")                             \
  S(U64, points_pushed, "points_pushed")               \
  S(U64, points_outside, "points_outside")             \
  S(U64, points_late, "points_late")                   \
  S(U64, points_glitch, "points_glitch")               \
  S(U64, points_overflow, "points_overflow")           \
  S(U64, points_after_flush, "points_after_flush")     \
  S(U64, windows, "windows")                           \
  S(U64, windows_overflowed, "windows_overflowed")     \
  S(U64, points_in_overflowed, "points_in_overflowed") \
  S(U64, objects_reported, "objects_reported")         \
  S(U64, objects_not_owned, "objects_not_owned")       \
  S(F64, furthest_along, "furthest_along")             \
  S(F64, done_until, "done_until")

#define SPINHASH_SCENE_OBJECT_KEYS(K)     \
  K("tile", "")                           \
  K("object", "")                         \
  K("kind", "kind")                       \
  K("status", "status")                   \
  K("model", "model")                     \
  K("confident", "confident")             \
  K("group_size", "group_size")           \
  K("class", "vehicle_class")             \
  K("class_confident", "class_confident") \
  K("class_ranking", "class_ranking")     \
  K("group", "group")                     \
  K("group_ranking", "group_ranking")     \
  K("levels", "levels")                   \
  K("level", "level")                     \
  K("score", "score")                     \
  K("ranking", "ranking")                 \
  K("pose", "pose")                       \
  K("ground_gap", "ground_gap")           \
  K("points", "points")                   \
  K("center", "center")                   \
  K("extent", "extent")                   \
  K("heading_deg", "heading_deg")

#endif /* SPINHASH_SCENE_FIELDS_H */
