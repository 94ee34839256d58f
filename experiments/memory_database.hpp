// A database built and opened in memory (the same content and validation as
// `spinhash build` + Database::open, without the file).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_content.hpp"
#include "db/database_builder.hpp"
#include "spinhash/database.hpp"

namespace spinhash::experiment {

struct MemoryDatabase {
  host::BlobContent content;  // kept for experiments that rebuild parts (LSH)
  host::AlignedBytes bytes;   // the blob; `db` points into it
  Database db;
  host::BuildReport report;
  double build_seconds = 0.0;      // features + grids + LSH (build_database)
  double serialize_seconds = 0.0;  // blob writing and validation
  uint64_t blob_bytes = 0;
};

// Builds from model clouds with `options`; nullptr with *error on failure.
// keep_content: keep the BlobContent (else it is freed after serialising).
std::unique_ptr<MemoryDatabase> build_memory_database(const std::vector<host::ModelCloud>& clouds,
                                                      const host::BuildOptions& options, bool keep_content,
                                                      std::string* error);

}  // namespace spinhash::experiment
