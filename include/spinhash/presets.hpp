// Named recognizer configurations: the one place their values live. The
// command line (`--preset`), the experiments (`--preset`), the instruction
// benchmark's target runner (`preset=flight`) and firmware all take them from
// here. docs/results.md measures what each costs and gains.
#pragma once
#include <cstdint>
#include <cstring>

#include "spinhash/config.hpp"

namespace spinhash {

enum class Preset : uint8_t {
  kDefault = 0,  // RecognizerConfig{}: the accuracy of docs/results.md
  kFlight = 1,   // a flight budget: about a third of the default's instructions per query
  kFull = 2,     // the full recognition; today the default's settings
};

// kFlight trades accuracy for instructions: a coarser query voxel (fewer
// points described), fewer query features, a shorter LSH scan, fewer
// candidates per feature, fewer features verified per hypothesis and the
// draws' budget halved. docs/results.md gives its instructions per query
// and its accuracy against the default's.
constexpr float kFlightQueryVoxel = 0.18f;       // m: the query's density voxel (extract.query_cloud_voxel)
constexpr uint32_t kFlightMaxFeatures = 256;     // s: query features kept (evenly thinned)
constexpr uint32_t kFlightMaxBucketScan = 512;   // LSH entries scanned per query feature
constexpr uint32_t kFlightTopW = 30;             // W: candidates per query feature
constexpr uint32_t kFlightVerifyFeatures = 128;  // query features scored per hypothesis
constexpr uint32_t kFlightMaxTrials = 800;       // BRAN's draws

// Sets the fields a preset names; every other field keeps its value.
inline void apply_preset(Preset preset, RecognizerConfig* c) {
  if (preset != Preset::kFlight) return;
  c->extract.query_cloud_voxel = kFlightQueryVoxel;
  c->max_features = kFlightMaxFeatures;
  c->candidates.max_bucket_scan = kFlightMaxBucketScan;
  c->candidates.top_w = kFlightTopW;
  c->draws.verify_features = kFlightVerifyFeatures;
  c->draws.max_trials = kFlightMaxTrials;
}

inline RecognizerConfig preset_config(Preset preset) {
  RecognizerConfig c;
  apply_preset(preset, &c);
  return c;
}

inline const char* preset_name(Preset preset) {
  return preset == Preset::kFlight ? "flight" : (preset == Preset::kFull ? "full" : "default");
}

// "default", "flight" or "full"; false for any other name.
inline bool preset_from_name(const char* name, Preset* preset) {
  if (std::strcmp(name, "default") == 0)
    *preset = Preset::kDefault;
  else if (std::strcmp(name, "flight") == 0)
    *preset = Preset::kFlight;
  else if (std::strcmp(name, "full") == 0)
    *preset = Preset::kFull;
  else
    return false;
  return true;
}

}  // namespace spinhash
