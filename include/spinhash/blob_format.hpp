// On-disk layout of a spinhash database blob (.shdb), format v5.
// docs/blob-format.md is the normative description; these structs mirror it.
// All integers and floats are stored in the byte order named by the header.
#pragma once
#include <cstdint>

#include "spinhash/answer_levels.h"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace blob {

constexpr char kMagic[8] = {'S', 'P', 'I', 'N', 'H', 'S', 'H', 'D'};
// v5: the Calibration section; v4: a vehicle class per model; v3: normals
// up within 45 degrees of vertical; v2: the nearest-feature field.
constexpr uint32_t kFormatVersion = 5;
constexpr uint32_t kByteOrderMark = 0x01020304u;  // reads 0x04030201 on the other byte order
constexpr uint32_t kSectionAlignment = 64;

// 64 bytes at offset 0.
struct Header {
  char magic[8];
  uint32_t version;
  uint32_t byte_order;          // kByteOrderMark in the writer's order
  uint64_t total_size;          // bytes, the whole blob
  uint64_t config_fingerprint;  // FNV-1a 64 of the Params section bytes
  uint32_t section_count;       // <= kMaxSections
  uint32_t header_crc;          // CRC-32C of header (this field as 0) + section table
  uint8_t reserved[24];         // zero
};
static_assert(sizeof(Header) == 64, "header is 64 bytes");

enum SectionId : uint32_t {
  kParams = 1,         // Params, one
  kModels = 2,         // ModelRecord[model_count]
  kFeatPositions = 3,  // float[3 * feature_count], model frame, metres
  kFeatNormals = 4,    // int16[3 * feature_count], unit normal * 32767
  kFeatModels = 5,     // uint16[feature_count], model index of each feature
  kFeatSpins = 6,      // uint8[spin_dims * feature_count], quantised spin images
  kGridOffsets = 7,    // uint32[grid_offset_count], per-model CSR cell offsets
  kLshBits = 8,        // LshBit[lsh_tables * lsh_bits]
  kLshOffsets = 9,     // uint32[lsh_tables * (lsh_buckets + 1)], CSR per table
  kLshEntries = 10,    // uint32[lsh_tables * feature_count], feature indices
  kNearestField = 11,  // uint16[field_entry_count], per-model voxel slots (NearestField below)
  kCalibration = 12,   // CalibrationHeader, CalibrationPass[pass_count], CalibrationCell[...] (below)
};
constexpr uint32_t kSectionIdCount = 12;

// 32 bytes each, immediately after the header.
struct SectionEntry {
  uint32_t id;
  uint32_t reserved;   // zero
  uint64_t offset;     // from blob start, multiple of kSectionAlignment
  uint64_t size;       // bytes of payload (padding after it is not counted)
  uint32_t crc;        // CRC-32C of the payload
  uint32_t reserved2;  // zero
};
static_assert(sizeof(SectionEntry) == 32, "section entry is 32 bytes");

// The kParams section: 128 bytes.
struct Params {
  uint32_t model_count;
  uint32_t feature_count;
  uint32_t bins_alpha;
  uint32_t bins_beta;
  uint32_t lsh_tables;         // L
  uint32_t lsh_bits;           // K
  uint32_t lsh_buckets;        // buckets per table, a power of two
  uint32_t grid_offset_count;  // entries of kGridOffsets
  float cloud_voxel;
  float normal_radius;
  float basis_spacing;  // spacing used for the model features
  float support_radius;
  float support_angle_deg;
  float spin_quant_scale;
  float lsh_dc;                // d_c of eq. 2: sum of per-dimension ranges, quantised units
  float grid_cell;             // m, cell edge of every model's feature grid
  uint32_t field_entry_count;  // entries of kNearestField (0: no field)
  uint32_t field_slots;        // slots per voxel, <= kMaxFieldSlots (0: no field)
  float field_cell;            // m, voxel edge of the field (0: no field)
  float field_reach;           // m, the field holds features within this of a voxel
  uint8_t reserved[48];        // zero
};
static_assert(sizeof(Params) == 128, "params are 128 bytes");

// One per model, kModels section: 128 bytes. Features of model i are
// [first_feature, first_feature + feature_count), sorted by grid cell.
struct ModelRecord {
  char name[kMaxModelNameBytes];  // NUL-terminated, rest zero
  uint32_t first_feature;
  uint32_t feature_count;
  uint32_t grid_dims[3];      // cells along x, y, z (each >= 1)
  uint32_t grid_offset_base;  // index into kGridOffsets; cells+1 entries,
                              // values relative to first_feature, last == feature_count
  float grid_origin[3];       // m, model frame, min corner of cell (0,0,0)
  float bbox_min[3];          // m, of the model cloud
  float bbox_max[3];
  uint32_t field_dims[3];  // voxels along x, y, z of the nearest-feature field (0 when none)
  uint32_t field_base;     // index into kNearestField of voxel (0,0,0)'s first slot
  uint8_t vehicle_class;   // < kVehicleClassCount (vehicle_classes.h; 0: unclassified)
  uint8_t vehicle_group;   // 0: the class's group; else the model's own (< kVehicleGroupCount),
                           // only for a class in no group (vehicle_group_of(class, own))
  uint8_t reserved[2];     // zero (pads the record to 128 bytes)
};
static_assert(sizeof(ModelRecord) == 128, "model record is 128 bytes");

// Nearest-feature field (kNearestField): per model, a dense voxel grid of
// field_dims voxels of edge field_cell whose corner (0,0,0) lies field_reach
// below grid_origin on every axis; voxel (i, j, k) holds field_slots model
// features (indices relative to first_feature; kNoFieldFeature pads) at
// field_base + field_slots * (i + dims[0] * (j + dims[1] * k)). The slots are
// the features nearest the voxel's centre within field_reach plus the voxel's
// half-diagonal, one per surface orientation: each slot's normal differs from
// every nearer slot's by more than the builder's split angle (edges and corners
// keep a feature of every face). Verification looks a warped query feature up
// in O(field_slots) instead of searching the grid.
constexpr uint16_t kNoFieldFeature = 0xFFFFu;

// One sampled bit of eq. 2: bit = spin[dim] > threshold (quantised units).
struct LshBit {
  uint16_t dim;
  uint16_t threshold;
};
static_assert(sizeof(LshBit) == 4, "lsh bit is 4 bytes");

// Key of a spin image in table t: bit k (k = 0..K-1, least significant first) is
// spin[bits[t*K + k].dim] > bits[t*K + k].threshold.
// Bucket of that key: mix64(key ^ ((t + 1) * kTableSalt)) & (lsh_buckets - 1),
// products modulo 2^64 (t + 1 so that table 0 is salted too).
constexpr uint64_t kTableSalt = 0x9E3779B97F4A7C15ull;
inline uint64_t mix64(uint64_t x) {  // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return x;
}
inline uint32_t bucket_of(uint64_t key, uint32_t table, uint32_t buckets) {
  return static_cast<uint32_t>(mix64(key ^ (static_cast<uint64_t>(table + 1) * kTableSalt)) & (buckets - 1u));
}

// Calibration (kCalibration): per pass of the recognizer, per calibrated
// answer level (answer_levels.h: vehicle, group, class, model) and per band
// of scan density, the evidence threshold of the level's flag and what the
// build's fit expects of it. The payload is the header, then pass_count
// CalibrationPass records, then pass_count x kCalibratedLevels x band_count
// cells, pass-major, then level, then band (densest last).
constexpr uint32_t kMaxCalibrationPasses = 4;
constexpr uint32_t kMaxDensityBands = 16;

// The clutter the calibration scanned (CalibrationHeader::clutter): each
// level's flag holds its precision against that clutter, not against others.
enum CalibrationClutter : uint32_t {
  kClutterTiles = 0,         // trees, walls, crates and buildings: what tiles hold
  kClutterVehicleSized = 1,  // those, and sheds, freight containers, bushes and heaps
};

// 128 bytes.
struct CalibrationHeader {
  uint32_t pass_count;     // 1..kMaxCalibrationPasses
  uint32_t level_count;    // kCalibratedLevels
  uint32_t band_count;     // 1..kMaxDensityBands
  float target_precision;  // (0, 1]: the precision each fitted threshold reaches on the runs
  // Band b holds densities in [band_min_density[b], band_min_density[b + 1])
  // points per m^2 (RecognitionStats::scan_density); the last band is open
  // above. band_min_density[0] == 0, strictly increasing; entries from
  // band_count on are zero.
  float band_min_density[kMaxDensityBands];
  uint32_t scans_per_model;     // calibration scans of each model (0: not fitted)
  uint32_t models_left_out;     // models recognised with a database that lacks them
  uint32_t clutter_scans;       // scans of clutter, its kinds in turn
  uint32_t scans_per_left_out;  // scans of each model left out (at least scans_per_model)
  uint64_t seed;                // of the calibration scans
  uint32_t clutter;             // CalibrationClutter: the kinds scanned
  uint8_t reserved[20];         // zero
};
static_assert(sizeof(CalibrationHeader) == 128, "calibration header is 128 bytes");

// Where a pass's thresholds come from.
enum CalibrationSource : uint32_t {
  kSourcePriors = 0,  // none fitted: the recognizer's settings decide (its cells are all zero)
  kSourceFitted = 1,  // fitted by the build from the database's own models
};

// 16 bytes.
struct CalibrationPass {
  uint32_t pass;    // id in SPINHASH_CALIBRATION_PASSES; pass record i holds pass i
  uint32_t source;  // CalibrationSource
  uint32_t runs;    // recognitions the fit drew on (0 for priors)
  // The precision this pass's fitted thresholds reach, in (0, 1]; 0: the
  // header's (always 0 for priors).
  float target_precision;
};
static_assert(sizeof(CalibrationPass) == 16, "calibration pass is 16 bytes");

// The precision a pass's table was fitted to: its record's own, else the header's.
inline float pass_target_precision(const CalibrationHeader& h, const CalibrationPass& p) {
  return p.target_precision > 0.0f ? p.target_precision : h.target_precision;
}

// What a cell says.
enum CalibrationState : uint32_t {
  kCellPriors = 0,       // a priors pass's cell: all fields zero
  kCellFitted = 1,       // confident when evidence >= threshold
  kCellTooFew = 2,       // never confident: too few calibration runs in the band
  kCellUnreachable = 3,  // never confident: no threshold reaches the target precision
};

// 32 bytes.
struct CalibrationCell {
  float threshold;     // evidence at or above which the level is confident (kCellFitted)
  float precision;     // on the calibration runs in the band at that threshold, in [0, 1]
  float recall;        // share of the band's right answers flagged, in [0, 1]
  uint32_t positives;  // runs in the band whose answer at this level was right
  uint32_t negatives;  // runs in the band whose answer at this level was wrong
  uint32_t flagged;    // runs in the band at or above the threshold
  uint32_t state;      // CalibrationState
  uint32_t reserved;   // zero
};
static_assert(sizeof(CalibrationCell) == 32, "calibration cell is 32 bytes");

}  // namespace blob
}  // namespace spinhash
