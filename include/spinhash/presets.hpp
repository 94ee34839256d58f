// Named recognizer configurations: the one place their values live. The
// command line (`--preset`), the experiments (`--preset`), the instruction
// benchmark's target runner (`preset=flight`) and firmware all take them from
// here. docs/results.md measures what each costs and gains.
#pragma once
#include <cstdint>
#include <cstring>

#include "spinhash/calibration.hpp"
#include "spinhash/config.hpp"

namespace spinhash {

enum class Preset : uint8_t {
  kDefault = 0,  // RecognizerConfig{}: the cascade, a flight pass first, the full pass when unsure
  kFlight = 1,   // the cascade's first pass alone: about a third of the full pass's instructions
  kFull = 2,     // the full pass alone (the cascade off)
};

// The cascade's first pass as a configuration of its own: the first_*
// fields of `c` in place of the full pass's (each at most the full pass's
// value, which sizes the workspace); cascade off.
inline void apply_first_pass(const RecognizerConfig& c, RecognizerConfig* pass) {
  auto at_most = [](uint32_t v, uint32_t full) { return v < full ? v : full; };
  *pass = c;
  pass->cascade = false;
  pass->extract.query_cloud_voxel = c.first_query_voxel;
  pass->max_features = at_most(c.first_features, c.max_features);
  pass->candidates.max_bucket_scan = at_most(c.first_bucket_scan, c.candidates.max_bucket_scan);
  pass->candidates.top_w = at_most(c.first_top_w, c.candidates.top_w);
  pass->draws.verify_features = c.first_verify_features;
  pass->draws.max_trials = c.first_trials;
  pass->confidence.min_margin = c.first_min_margin;
}

// The calibrated table that decides a one-pass run's flags: the first
// pass's when the config runs its own first pass's settings (the flight
// preset), else the full pass's. The cascade's first pass is always the
// first pass's.
inline AnswerPass calibration_pass(const RecognizerConfig& c) {
  RecognizerConfig first;
  apply_first_pass(c, &first);
  const bool same = !c.cascade && c.extract.query_cloud_voxel == first.extract.query_cloud_voxel &&
                    c.max_features == first.max_features &&
                    c.candidates.max_bucket_scan == first.candidates.max_bucket_scan &&
                    c.candidates.top_w == first.candidates.top_w &&
                    c.draws.verify_features == first.draws.verify_features &&
                    c.draws.max_trials == first.draws.max_trials &&
                    c.confidence.min_margin == first.confidence.min_margin;
  return same ? AnswerPass::kFirst : AnswerPass::kFull;
}

// Sets the fields a preset names; every other field keeps its value.
// kFlight: the cascade's first pass alone (fixed, lowest cost; its
// confidence margin the first pass's); kFull: the full pass alone.
inline void apply_preset(Preset preset, RecognizerConfig* c) {
  if (preset == Preset::kFlight) apply_first_pass(*c, c);
  if (preset == Preset::kFull) c->cascade = false;
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
