// A database blob read from disk and opened (validated) by the core.
#pragma once
#include <string>

#include "blob/aligned_bytes.hpp"
#include "spinhash/database.hpp"

namespace spinhash::pipeline {

struct DatabaseFile {
  host::AlignedBytes bytes;
  Database db;
};

// false with a message naming the file and the core's status on any failure.
bool load_database(const std::string& path, DatabaseFile* out, std::string* error);

}  // namespace spinhash::pipeline
