// The measurements behind `experiment lsh`, on a database built in memory
// and features of simulated query scans whose true model and pose are known.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lsh_data.hpp"
#include "memory_database.hpp"
#include "query_set.hpp"
#include "spinhash/config.hpp"

namespace spinhash::experiment {

// A query feature with its exhaustive (brute-force L1) answer.
struct ProbeFeature {
  std::vector<uint8_t> spin;           // quantised with the database's scale
  Eigen::Vector3d position;            // query frame
  uint32_t model = 0;                  // true model
  std::vector<uint32_t> correct;       // true-model features within Delta under the true pose
  uint32_t nn_distance = 0;            // raw L1 to the nearest database feature
  uint32_t w_distance = 0;             // raw L1 to the W-th nearest
  bool exhaustive_match = false;       // a correct feature within the exhaustive top W
  double exhaustive_true_share = 0.0;  // share of the exhaustive top W from the true model
};

// Features of `q` (the core's extractor, database parameters), at most
// per_query of them spread evenly, with their exhaustive answers.
bool probe_features(const MemoryDatabase& mdb, const RecognizerConfig& cfg, const Query& q,
                    uint32_t per_query, std::vector<ProbeFeature>* out, std::string* error);

// One (K, L): tables built like the builder's, recall of the W candidates
// of the core's LshSearcher, and key collisions of the first pair_features
// probes against every database feature, binned by clamped L1 distance.
bool measure_lsh_config(const MemoryDatabase& mdb, const host::BuildOptions& build,
                        const RecognizerConfig& cfg, const std::vector<ProbeFeature>& probes,
                        uint32_t pair_features, const std::vector<uint32_t>& ranges, double bin_width,
                        uint32_t bins, LshConfigResult* out, std::string* error);

}  // namespace spinhash::experiment
