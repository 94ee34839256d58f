// Parameters of feature extraction (fixed per database, stored in the blob)
// and of recognition (chosen per call). Symbols in comments are the paper's.
#pragma once
#include <cstdint>

#include "spinhash/stage_fields.h"

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

// The stages' parameters (stage_fields.h: each field's default, range and
// why), one struct per stage, e.g. DrawsParams: generated from the lists.
#define SPINHASH_CXX_TYPE_BOOL bool
#define SPINHASH_CXX_TYPE_U32 uint32_t
#define SPINHASH_CXX_TYPE_F32 float
#define SPINHASH_CXX_PARAMS_MEMBER(kind, name, def, lo, hi, flag, why) SPINHASH_CXX_TYPE_##kind name = def;
#define SPINHASH_CXX_PARAMS_STRUCT(id, Name, what)   \
  struct Name##Params {                              \
    SPINHASH_PARAMS_##id(SPINHASH_CXX_PARAMS_MEMBER) \
  };
SPINHASH_STAGES(SPINHASH_CXX_PARAMS_STRUCT)
#undef SPINHASH_CXX_PARAMS_STRUCT
#undef SPINHASH_CXX_PARAMS_MEMBER

// One pass of the stages: every stage's parameters, one member per stage
// named by its id (config.draws.max_trials).
struct StageParams {
#define SPINHASH_CXX_STAGE_MEMBER(id, Name, what) Name##Params id;
  SPINHASH_STAGES(SPINHASH_CXX_STAGE_MEMBER)
#undef SPINHASH_CXX_STAGE_MEMBER
};

// The cascade's first pass: the flight settings (presets.hpp), cheap enough
// that a query it answers confidently costs a third of the full pass. Each
// value is at most the full pass's (a larger one is cut to it: the
// workspace is carved for the full pass).
constexpr float kFlightQueryVoxel = 0.18f;       // m: the query's density voxel (fewer points described)
constexpr uint32_t kFlightMaxFeatures = 256;     // s: query features kept (evenly thinned)
constexpr uint32_t kFlightMaxBucketScan = 512;   // LSH entries scanned per query feature
constexpr uint32_t kFlightTopW = 30;             // W: candidates per query feature
constexpr uint32_t kFlightVerifyFeatures = 128;  // query features scored per hypothesis
constexpr uint32_t kFlightMaxTrials = 700;       // BRAN's draws: the median query in 50 M, right first held
// The first pass's confidence margin (ConfidenceParams::min_margin): its
// confident answer ends the query, so it must be right as often as the full
// pass's on fewer, coarser features.
constexpr float kFirstPassMinMargin = 1.2f;
// Work units a query may spend (work_meter.hpp; 63-99 aarch64
// instructions a unit): a bound on the worst query that no query of the
// fleet's accuracy sets reaches. 4 000 000 holds the instruction
// benchmark's worst query under 300 M aarch64 instructions but caps dense
// noisy fleet scans and costs right answers there (docs/budgets.md).
constexpr uint64_t kDefaultMaxWork = 12000000u;

// Recognition settings: the mode, the seed, the capacities that size the
// workspace (max_*), the viewpoint (config_fields.h), and the stages'
// parameters (StageParams). Defaults are the paper's setting where it gives
// one.
struct RecognizerConfig : StageParams {
  Mode mode = Mode::kBran;
  uint64_t seed = 1;  // deterministic sampling

  // Capacities: inputs above them are refused (points) or thinned (features).
  uint32_t max_points = 32768;    // raw query points used (more: thinned evenly, or refused)
  bool thin_large_clouds = true;  // false: a cloud above max_points is refused (kTooManyPoints)
  uint32_t max_features = 1024;   // s: query basis points kept
  uint32_t max_models = 2048;     // m: database models supported by this workspace
  uint32_t max_spin_dims = 256;   // d: largest spin image (bins_alpha * bins_beta) supported

  // Optional sensor position in input coordinates: normals are turned towards it.
  bool has_viewpoint = false;
  double viewpoint[3] = {0.0, 0.0, 0.0};

  // The cascade (recognizer.cpp): a first pass at these settings (the
  // flight preset's); when it does not stop the query (confident, or the
  // agree table's), the full pass at the fields above (starting from the
  // first pass's leading poses only with carry.enabled).
  bool cascade = true;
  float first_query_voxel = kFlightQueryVoxel;
  uint32_t first_features = kFlightMaxFeatures;
  uint32_t first_bucket_scan = kFlightMaxBucketScan;
  uint32_t first_top_w = kFlightTopW;
  uint32_t first_verify_features = kFlightVerifyFeatures;
  uint32_t first_trials = kFlightMaxTrials;
  float first_min_margin = kFirstPassMinMargin;
  // The hard cap over both passes (work_meter.hpp).
  uint64_t max_work = kDefaultMaxWork;
};

}  // namespace spinhash
