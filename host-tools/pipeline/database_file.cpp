#include "pipeline/database_file.hpp"

#include "blob/file_io.hpp"

namespace spinhash::pipeline {

bool load_database(const std::string& path, DatabaseFile* out, std::string* error) {
  if (!host::read_file(path, &out->bytes, error)) return false;
  if (out->bytes.empty()) {
    *error = path + ": empty file, not a database";
    return false;
  }
  Status s = Database::open(out->bytes.data(), out->bytes.size(), &out->db);
  if (s != Status::kOk) {
    *error = path + ": " + status_name(s);
    return false;
  }
  return true;
}

}  // namespace spinhash::pipeline
