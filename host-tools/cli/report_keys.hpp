// The keys of `info --format json` and `verify --format json`, and the class
// keys of `recognize` and `scene`, defined once:
// the writers (cmd_info.cpp, cmd_verify.cpp) use these constants and
// tests/host/test_field_mirrors.cpp checks every one against docs/cli.md and
// the command's output.
#pragma once
#include "pipeline/class_json.hpp"

namespace spinhash::cli {

namespace info_keys {
constexpr const char* kFormat = "format";  // blob format version
constexpr const char* kBytes = "bytes";
constexpr const char* kBytesPerFeature = "bytes_per_feature";
constexpr const char* kFingerprint = "fingerprint";  // config fingerprint, 16 hex digits
constexpr const char* kModels = "models";
constexpr const char* kFeatures = "features";
constexpr const char* kSpinImages = "spin_images";  // object: bins, radius, support_angle, quant_scale
constexpr const char* kBins = "bins";
constexpr const char* kRadius = "radius";
constexpr const char* kSupportAngle = "support_angle";
constexpr const char* kQuantScale = "quant_scale";
constexpr const char* kSampling = "sampling";  // object: voxel, normal_radius, basis_spacing
constexpr const char* kVoxel = "voxel";
constexpr const char* kNormalRadius = "normal_radius";
constexpr const char* kBasisSpacing = "basis_spacing";
constexpr const char* kLsh = "lsh";  // object: tables, bits, buckets, d_c
constexpr const char* kTables = "tables";
constexpr const char* kBits = "bits";
constexpr const char* kBuckets = "buckets";
constexpr const char* kDc = "d_c";
constexpr const char* kGrid = "grid";  // object: cell, offsets
constexpr const char* kCell = "cell";
constexpr const char* kOffsets = "offsets";
constexpr const char* kField = "nearest_field";  // object: cell, reach, slots, entries (cell 0: none)
constexpr const char* kReach = "reach";
constexpr const char* kSlots = "slots";
constexpr const char* kEntries = "entries";
constexpr const char* kModelList = "model_list";  // [{name, class, group, features, extent}]
constexpr const char* kName = "name";
constexpr const char* kClass = "class";  // the model's vehicle class (vehicle_classes.h)
constexpr const char* kGroup = "group";  // its group: its class's, or its own (vehicle_classes.h)
constexpr const char* kExtent = "extent";
// object: target_precision, scans_per_model, models_left_out, clutter_scans, clutter, seed, bands, passes
constexpr const char* kCalibration = "calibration";
constexpr const char* kTargetPrecision = "target_precision";
constexpr const char* kScansPerModel = "scans_per_model";
constexpr const char* kModelsLeftOut = "models_left_out";
constexpr const char* kClutterScans = "clutter_scans";
constexpr const char* kClutter = "clutter";  // "tiles" or "vehicle-sized" (blob::CalibrationClutter)
constexpr const char* kScansPerLeftOut = "scans_per_left_out";
constexpr const char* kSeed = "seed";
constexpr const char* kBands = "bands";    // the density bands' lower edges, points per m^2
constexpr const char* kPasses = "passes";  // [{pass, source, target_precision, runs, levels}]
constexpr const char* kPass = "pass";
constexpr const char* kSource = "source";  // "fitted" or "priors"
constexpr const char* kRuns = "runs";
constexpr const char* kLevels = "levels";  // [{level, cells}]
constexpr const char* kLevel = "level";
constexpr const char* kCells =
    "cells";  // per band: [{state, threshold, precision, recall, positives, negatives, flagged}]
constexpr const char* kState = "state";
constexpr const char* kThreshold = "threshold";
constexpr const char* kPrecision = "precision";
constexpr const char* kRecall = "recall";
constexpr const char* kPositives = "positives";
constexpr const char* kNegatives = "negatives";
constexpr const char* kFlagged = "flagged";
constexpr const char* kAll[] = {kFormat,
                                kBytes,
                                kBytesPerFeature,
                                kFingerprint,
                                kModels,
                                kFeatures,
                                kSpinImages,
                                kBins,
                                kRadius,
                                kSupportAngle,
                                kQuantScale,
                                kSampling,
                                kVoxel,
                                kNormalRadius,
                                kBasisSpacing,
                                kLsh,
                                kTables,
                                kBits,
                                kBuckets,
                                kDc,
                                kGrid,
                                kCell,
                                kOffsets,
                                kField,
                                kReach,
                                kSlots,
                                kEntries,
                                kModelList,
                                kName,
                                kClass,
                                kGroup,
                                kExtent,
                                kCalibration,
                                kTargetPrecision,
                                kScansPerModel,
                                kModelsLeftOut,
                                kClutterScans,
                                kClutter,
                                kScansPerLeftOut,
                                kSeed,
                                kBands,
                                kPasses,
                                kPass,
                                kSource,
                                kRuns,
                                kLevels,
                                kLevel,
                                kCells,
                                kState,
                                kThreshold,
                                kPrecision,
                                kRecall,
                                kPositives,
                                kNegatives,
                                kFlagged};
}  // namespace info_keys

namespace verify_keys {
constexpr const char* kIntegrity = "integrity";  // "ok" or "failed"
constexpr const char* kError = "error";          // why, when integrity failed
constexpr const char* kModels = "models";
constexpr const char* kFeatures = "features";
constexpr const char* kMode = "mode";
constexpr const char* kNoise = "noise";
constexpr const char* kScans = "scans";      // self-recognition scans made (0 without meshes)
constexpr const char* kHits = "hits";        // of them, ranked their own model first
constexpr const char* kMissing = "missing";  // meshes whose model is not in the database
constexpr const char* kMisses = "misses";    // [{model, scan, ranked_first | status}]
constexpr const char* kModel = "model";
constexpr const char* kScan = "scan";
constexpr const char* kRankedFirst = "ranked_first";
constexpr const char* kStatus = "status";
constexpr const char* kCalibration = "calibration";  // "fitted" or "priors"
// [{pass, level, flagged, wrong, precision, expected_precision, recall, expected_recall, agrees}]:
// the calibration re-run, every fitted pass (empty without meshes or a fitted calibration)
constexpr const char* kCalibrationCheck = "calibration_check";
constexpr const char* kPass = "pass";  // "full", "first" (answer_levels.h)
constexpr const char* kLevel = "level";
constexpr const char* kFlagged = "flagged";
constexpr const char* kWrong = "wrong";
constexpr const char* kPrecision = "precision";
constexpr const char* kExpectedPrecision = "expected_precision";
constexpr const char* kRecall = "recall";
constexpr const char* kExpectedRecall = "expected_recall";
constexpr const char* kAgrees = "agrees";
constexpr const char* kAll[] = {kIntegrity,   kError,
                                kModels,      kFeatures,
                                kMode,        kNoise,
                                kScans,       kHits,
                                kMissing,     kMisses,
                                kModel,       kScan,
                                kRankedFirst, kStatus,
                                kCalibration, kCalibrationCheck,
                                kPass,        kLevel,
                                kFlagged,     kWrong,
                                kPrecision,   kExpectedPrecision,
                                kRecall,      kExpectedRecall,
                                kAgrees};
}  // namespace verify_keys

// The class keys of `recognize` and `scene` JSON lines: one list, in
// pipeline/class_json.hpp (the survey writes them too).
namespace class_keys = pipeline::class_keys;

}  // namespace spinhash::cli
