// Compile-time bounds of the core. Every loop in firmware-lib is bounded by
// one of these or by a config capacity checked against them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>

namespace spinhash {

constexpr size_t kBufferAlignment = 64;       // blob and workspace base alignment
constexpr uint32_t kMaxSpinBinsPerAxis = 32;  // spin image bins along alpha or beta
constexpr uint32_t kMaxSpinDims = kMaxSpinBinsPerAxis * kMaxSpinBinsPerAxis;  // d
constexpr uint32_t kMaxLshBits = 64;      // K: bits per key (one uint64 key)
constexpr uint32_t kMaxLshTables = 64;    // L
constexpr uint32_t kMaxCandidates = 128;  // W: candidates kept per query feature
// Largest ground clearance, m (GroundParams::ground_clearance).
constexpr float kMaxGroundClearance = 10.0f;
// BRAN's draws while min_hypotheses is not met: at most this many times
// DrawsParams::max_trials (the work budget stays bounded).
constexpr uint32_t kTrialExtension = 4;
// Largest DrawsParams::max_trials: the extended budget fits uint32.
constexpr uint32_t kMaxTrials = 0xFFFFFFFFu / kTrialExtension;
// RecognizerConfig::max_work: work units (work_meter.hpp) a query may spend.
constexpr uint64_t kMaxQueryWork = 1ull << 40;
// CarryParams::carry_models: the first pass's leading poses kept for the
// full pass (an array in the workspace).
constexpr uint32_t kMaxCarriedPoses = 16;
// Bounds of the stages' counts (stage_fields.h): each sizes an array or
// bounds a loop of its stage.
constexpr uint32_t kMaxTransferModels = 64;    // TransferParams::transfer_models
constexpr uint32_t kMaxTransferPoses = 16;     // TransferParams::transfer_poses
constexpr uint32_t kMaxFocusModels = 64;       // FocusParams::focus_models
constexpr uint32_t kMaxRescoredModels = 16;    // RefineParams::rescored_models (an array on the stack)
constexpr uint32_t kMaxRefineIterations = 16;  // RefineParams::refine_iterations
constexpr uint32_t kMaxLendModels = 32;        // RefineParams::lend_spread_models, lend_family_models
constexpr uint32_t kMaxLendRounds = 8;         // RefineParams::lend_rounds
constexpr uint32_t kMaxGroupFitModels = 64;    // ClassesParams::group_fit_models
constexpr uint32_t kMaxNormalRadiusSteps = 8;  // ExtractParams::max_radius_steps
constexpr uint32_t kMaxGroundFitRounds = 16;   // GroundParams::fit_rounds
constexpr uint32_t kMaxBucketScan = 1u << 24;  // CandidatesParams::max_bucket_scan, max_sparse_bucket_scan
constexpr uint32_t kMaxSparseScale =
    64;  // CandidatesParams::sparse_scan_scale, DrawsParams::sparse_trial_scale
// The object ground's grid over a cut-out's footprint (geometry/object_ground.hpp).
constexpr uint32_t kObjectGroundGridSide = 32;
constexpr uint32_t kObjectGroundCells = kObjectGroundGridSide * kObjectGroundGridSide;
constexpr uint32_t kMaxModelNameBytes = 48;            // including the terminating NUL
constexpr uint32_t kMaxModels = 65535;                 // model ids are stored as uint16
constexpr uint32_t kMaxFeatures = 0x7FFFFFFF;          // feature ids are uint32
constexpr uint32_t kMaxQueryPointsLimit = 1u << 22;    // hard ceiling for config.max_points
constexpr uint32_t kMaxQueryFeaturesLimit = 1u << 14;  // hard ceiling for config.max_features
constexpr uint32_t kMaxSections = 16;                  // section table entries in a blob
constexpr uint32_t kMinNormalNeighbours = 5;           // fewer -> the point gets no normal
constexpr uint32_t kMaxStabilityRetries = 32;          // attempts to draw a stable doublet (eq. 3)
constexpr uint32_t kMaxGridCellsPerModel = 1u << 20;
constexpr uint32_t kMaxFieldVoxelsPerModel = 1u << 24;  // nearest-feature field (blob_format.hpp)
constexpr uint32_t kMaxFieldSlots = 8;                  // features per field voxel
// The scene (scene.hpp, scene_stream.hpp): bounds of SceneConfig and
// StreamConfig, the ranges of scene_fields.h.
constexpr uint32_t kMaxSceneTopN = 64;              // ranking entries kept per object
constexpr uint32_t kMaxSceneObjects = 1u << 16;     // objects per window
constexpr uint32_t kMaxSceneTilePoints = 1u << 26;  // points per window
constexpr uint32_t kMaxSceneGridCells = 1u << 24;   // terrain or segmentation cells per window
constexpr float kMinWindowCore = 1.0f;              // m: window_core
constexpr float kMaxWindowEdge = 2000.0f;           // m: window_core, window_margin, object_margin
constexpr float kMinSceneTerrainCell = 0.05f;  // m: finer grids cost cells and add nothing at lidar densities
constexpr float kMaxSceneTerrainCell = 10.0f;  // m
constexpr float kMaxTerrainWindow = 500.0f;    // m: the terrain filter's widest opening
constexpr float kMaxTerrainSlope = 10.0f;      // rise per m
constexpr float kMaxTerrainDh = 100.0f;        // m: the terrain filter's height thresholds and low band
constexpr float kMaxTerrainNoiseReach = 10.0f;  // m: terrain_noise_reach
constexpr uint32_t kMaxTerrainNoiseCells = 8;  // cells each way a low-noise test looks (reach / cell, capped)
constexpr uint32_t kMaxTerrainNoiseSupport =
    (2u * kMaxTerrainNoiseCells + 1u) * (2u * kMaxTerrainNoiseCells + 1u) - 1u;  // every cell around
constexpr uint32_t kMaxTerrainWindows = 8;  // the terrain filter's openings (half-widths 1, 2, 4, ... cells)
// A strip's terrain: blocks that say which part covers a point (coarser
// blocks where a strip is wide), kTerrainBlocksPerReach of them across the
// terrain filter's reach; blocks that lie within that many of each other
// are one part, so parts lie farther apart than the filter reaches, and
// there are at most as many as blocks kTerrainBlocksPerReach + 1 apart.
constexpr uint32_t kMaxTerrainBlockSide = 32;
constexpr uint32_t kMaxTerrainBlocks = kMaxTerrainBlockSide * kMaxTerrainBlockSide;
constexpr uint32_t kTerrainBlocksPerReach = 4;
constexpr uint32_t kMaxTerrainParts =
    ((kMaxTerrainBlockSide + kTerrainBlocksPerReach) / (kTerrainBlocksPerReach + 1)) *
    ((kMaxTerrainBlockSide + kTerrainBlocksPerReach) / (kTerrainBlocksPerReach + 1));
constexpr float kMaxGroundHeight = 10.0f;  // m above the terrain that is still ground
constexpr float kMinSegmentCell = 0.02f;   // m
// Height bins of a segmentation cell's column: the bits of its mask.
constexpr uint32_t kSegmentColumnBins = 32;
constexpr float kMinColumnBin = 0.01f;     // m: SceneConfig::column_bin
constexpr float kMaxColumnBin = 10.0f;     // m
constexpr float kMaxSegmentCell = 10.0f;   // m
constexpr float kMaxSceneGate = 1000.0f;   // m: size gates, clearance and the layer split
constexpr float kMaxSizeMismatch = 10.0f;  // share of a model's length and width
constexpr uint32_t kMaxStreamBufferedPoints = 1u << 28;
constexpr uint32_t kMaxStripColumns = 1024;  // windows of a row sharing one terrain grid
constexpr uint32_t kMaxBandColumns = 64;     // SceneConfig::band_columns
// StreamConfig::jump_confirm_points: the held points' buffer.
constexpr uint32_t kMaxJumpConfirmPoints = 64;
constexpr float kMaxStreamExtent = 1.0e5f;  // m: swath edges, lag, jump and z offset
// The low end of a range open at 0 (v >= it: v > 0), and the high end of
// a range open above (max_ground_sink).
constexpr float kSmallestPositive = std::numeric_limits<float>::denorm_min();
constexpr float kNoUpperBound = std::numeric_limits<float>::infinity();

}  // namespace spinhash
