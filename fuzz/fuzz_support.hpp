// Shared by the fuzzers: a recognizer over any opened database, and the
// invariants every Result must satisfy whatever the input.
#pragma once
#include <cmath>
#include <cstdint>

#include "blob/aligned_bytes.hpp"
#include "fuzz_require.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash::fuzz {

// Small capacities and budgets keep each run in the tens of milliseconds under
// ASan and make thinning (points and features) reachable from short inputs.
inline RecognizerConfig small_config(Mode mode) {
  constexpr uint32_t kPoints = 1024;
  constexpr uint32_t kFeatures = 64;
  constexpr uint32_t kTrials = 50;
  constexpr uint32_t kSranTrials = 10;
  constexpr uint32_t kHypotheses = 200;
  constexpr uint32_t kBucketScan = 256;  // LSH entries per feature: the default 4096 dominates the run time
  RecognizerConfig cfg;
  cfg.mode = mode;
  cfg.max_points = kPoints;
  cfg.max_features = kFeatures;
  cfg.draws.max_trials = kTrials;
  cfg.draws.sran_trials = kSranTrials;
  cfg.draws.max_hypotheses = kHypotheses;
  cfg.candidates.max_bucket_scan = kBucketScan;
  return cfg;
}

// One recognizer with its own workspace.
struct Session {
  host::AlignedBytes workspace;
  Recognizer recognizer;
  Status init(const Database* db, const RecognizerConfig& cfg) {
    if (workspace.size() < required_workspace_bytes(cfg))
      workspace = host::AlignedBytes(required_workspace_bytes(cfg));
    return recognizer.init(db, cfg, workspace.data(), workspace.size());
  }
};

inline bool known_recognize_status(Status s) {
  return s == Status::kOk || s == Status::kEmptyCloud || s == Status::kTooManyPoints ||
         s == Status::kNotEnoughFeatures;
}

// What recognize() promises for any input of `count` points.
inline void check_result(const Result& r, const Database& db, uint32_t count, size_t workspace_bytes) {
  require(known_recognize_status(r.status), "unexpected status");
  require(r.stats.extract.points_in == count, "points_in != count");
  require(r.stats.extract.points_thinned <= count, "thinned more than given");
  require(r.stats.workspace_used <= workspace_bytes, "workspace overrun");
  if (r.status != Status::kOk) {
    require(!r.confident, "confident without a result");
    return;
  }
  require(r.ranking_count <= db.model_count(), "ranking longer than the model table");
  for (uint32_t i = 0; i < r.ranking_count; ++i) {
    const RankedModel& m = r.ranking[i];
    require(m.model < db.model_count(), "ranked model out of range");
    require(!std::isnan(m.score), "NaN score");
    // Sorted by score, except that the first two of a look-alike group are
    // ordered by their residuals (docs/api.md): either order, above the rest.
    const bool twins = i == 1 && r.group_size >= 2u;
    require(i == 0 || twins || !(m.score > r.ranking[i - 1].score), "ranking not sorted");
    require(i != 2 || !(m.score > r.ranking[0].score), "ranking not sorted below the first two");
    if (!m.has_pose) continue;
    for (float v : m.pose.rotation) require(std::isfinite(v), "non-finite rotation");
    for (double v : m.pose.translation) require(std::isfinite(v), "non-finite translation");
  }
  require(!r.confident || r.ranking_count > 0, "confident with an empty ranking");
}

}  // namespace spinhash::fuzz
