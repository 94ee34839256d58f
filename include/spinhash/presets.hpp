// Named recognizer configurations: the one place their values live. The
// command line (`--preset`), the experiments (`--preset`), the instruction
// benchmark's target runner (`preset=flight`) and firmware all take them from
// here. Values and their measured costs: docs/results.md section 9q.
#pragma once
#include <cstdint>
#include <cstring>

#include "spinhash/config.hpp"

namespace spinhash {

enum class Preset : uint8_t {
  kDefault = 0,  // RecognizerConfig{}: the accuracy of docs/results.md
  kFlight = 1,   // issue 29's flight budget: about 50 M instructions per query on aarch64 at 56 models
};

// kFlight: issue 29's flight budget, measured by scripts/flight-levers.sh
// (docs/results.md section 9q) on aarch64 at 56 models: 40.8 M instructions
// per query (the benchmark's middle of 6; worst 49.9 M, 1.22x) against
// 124.2 M (worst 251.6 M) for the default (stop 31, with the spin-image,
// moments and nearest kernels; 43.8 M against 145.4 M with verify_features
// 128 before them). It costs accuracy: right
// first 1 621 of 1 680 fleet and family queries against 1 652 (the fleet's noisy scans 199 and 202 of 224
// without and with ground against 213 and 211, the families 499 and 498 of 504 at 0.05 and 0.10 m against 503
// and 502), confident and right 82 % of the right against 96 %, and at 1 000 models 67 / 64 % right first
// against 82 / 78 % (0.05 / 0.10 m). The query's density voxel (FeatureParams::cloud_voxel for the query
// only), m: 2.25 times the database's 0.08 m.
constexpr float kFlightQueryVoxel = 0.18f;
constexpr uint32_t kFlightMaxFeatures = 256;     // s: query features kept (evenly thinned)
constexpr uint32_t kFlightMaxBucketScan = 512;   // LSH entries scanned per query feature
constexpr uint32_t kFlightTopW = 30;             // W: candidates per query feature
constexpr uint32_t kFlightVerifyFeatures = 128;  // query features scored per hypothesis
constexpr uint32_t kFlightMaxTrials = 800;  // BRAN's draws: the budget the figures above were measured at

// Sets the fields a preset names; every other field keeps its value.
inline void apply_preset(Preset preset, RecognizerConfig* c) {
  if (preset != Preset::kFlight) return;
  c->query_cloud_voxel = kFlightQueryVoxel;
  c->max_features = kFlightMaxFeatures;
  c->max_bucket_scan = kFlightMaxBucketScan;
  c->top_w = kFlightTopW;
  c->verify_features = kFlightVerifyFeatures;
  c->max_trials = kFlightMaxTrials;
}

inline RecognizerConfig preset_config(Preset preset) {
  RecognizerConfig c;
  apply_preset(preset, &c);
  return c;
}

inline const char* preset_name(Preset preset) { return preset == Preset::kFlight ? "flight" : "default"; }

// "default" or "flight"; false for any other name.
inline bool preset_from_name(const char* name, Preset* preset) {
  if (std::strcmp(name, "default") == 0)
    *preset = Preset::kDefault;
  else if (std::strcmp(name, "flight") == 0)
    *preset = Preset::kFlight;
  else
    return false;
  return true;
}

}  // namespace spinhash
