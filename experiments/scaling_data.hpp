// What `experiment scaling` measured: per database size, the build and one
// record per (query, mode).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "query_runner.hpp"
#include "spinhash/config.hpp"

namespace spinhash::experiment {

struct BuildPoint {
  uint32_t models = 0;
  uint32_t features = 0;
  double build_seconds = 0.0;      // features, grids, LSH
  double serialize_seconds = 0.0;  // blob image and its validation
  uint64_t blob_bytes = 0;
  uint32_t max_bucket = 0;
  double mean_bucket = 0.0;
};

struct ScalingRecord {
  uint32_t size = 0;   // index into ScalingRun::builds
  uint32_t mode = 0;   // index into ScalingRun::modes
  uint32_t query = 0;  // index into the shared query set
  uint32_t model = 0;  // the scanned model
  Outcome outcome;
};

struct ScalingRun {
  std::string out_dir;
  std::string command;
  std::string recognizer;  // config_text of the defaults
  std::string database;    // config_text of the largest database
  std::vector<Mode> modes;
  std::vector<BuildPoint> builds;  // one per size, ascending
  uint32_t queries = 0;
  uint32_t query_pool = 0;          // queries come from models [0, query_pool)
  uint32_t sran_queries_large = 0;  // SRAN's queries at sizes >= sran_large_from
  uint32_t sran_large_from = 0;
  double noise = 0.0;
  double spacing = 0.0;           // m between query rays at the object
  std::string source;             // procedural fleet, or meshes and their look-alike copies
  uint32_t query_pool_cap = ~0u;  // with look-alike copies: the originals
  double scan_seconds = 0.0;      // model scans of the largest fleet (once)
  std::vector<ScalingRecord> records;
};

bool write_scaling_report(const ScalingRun& run, std::string* error);

}  // namespace spinhash::experiment
