// What `experiment lsh` measured: eq. 2 against observed key collisions, and
// how much of the exhaustive answer the W candidates of the index keep.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::experiment {

struct LshConfigResult {
  uint32_t k = 0, l = 0;    // bits per key, tables
  bool is_default = false;  // BuildOptions' K and L
  uint32_t buckets = 0;     // per table
  uint32_t max_bucket = 0;
  double mean_bucket = 0.0;
  // Collisions: per distance bin, pairs seen and pairs sharing a key in >= 1 table.
  std::vector<uint64_t> pairs, collisions;
  // Recall over the sampled query features.
  uint32_t features = 0;             // sampled query features
  uint32_t features_with_match = 0;  // those with a true model feature within Delta
  double nn_recall = 0.0;            // the exhaustive nearest neighbour is among the candidates
  double topw_recall = 0.0;          // share of the exhaustive top W among the candidates
  double match_recall = 0.0;         // a geometrically correct model feature is among the candidates
  double true_model_share = 0.0;     // candidates that belong to the true model
  double mean_candidates = 0.0;
  double mean_entries_scanned = 0.0;
  double truncated_share = 0.0;  // lookups cut by max_bucket_scan
  double us_per_lookup = 0.0;    // wall time of one search
};

struct LshRun {
  std::string out_dir, command, source, database;
  uint32_t top_w = 0, max_bucket_scan = 0;
  float delta = 0.0f;               // m: "geometrically correct" radius (RecognizerConfig::delta)
  double d_c = 0.0;                 // eq. 2's d_c (sum of clamped ranges), quantised units
  bool d_c_matches_builder = true;  // our reconstruction of C_i agrees with the builder's d_c
  double bin_width = 0.0;           // distance bin width, quantised units
  uint32_t bins = 0;                // over [0, bins * bin_width); farther pairs are not binned
  uint32_t queries = 0;
  uint32_t pair_features = 0;  // query features paired with every database feature
  uint64_t database_features = 0;
  double exhaustive_match_recall = 0.0;  // upper bound: a correct feature in the exhaustive top W
  double exhaustive_true_model_share = 0.0;
  double median_nn_distance = 0.0;     // clamped L1 units, of the sampled features
  double median_match_distance = 0.0;  // clamped L1 to the nearest correct model feature
  std::vector<LshConfigResult> configs;
};

bool write_lsh_report(const LshRun& run, std::string* error);

}  // namespace spinhash::experiment
