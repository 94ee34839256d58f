#include "pipeline/database_file.hpp"

#include <cstring>

#include "blob/byte_order.hpp"
#include "blob/file_io.hpp"

namespace spinhash::pipeline {
namespace {

// Why `bytes` were refused; for another format version, which one and what to do.
std::string refusal(const host::AlignedBytes& bytes, Status s) {
  std::string why = status_name(s);
  if (s != Status::kBlobUnsupportedVersion || bytes.size() < sizeof(blob::Header)) return why;
  blob::Header h;
  std::memcpy(&h, bytes.data(), sizeof h);
  const bool swapped = h.byte_order == host::byteswap_scalar(blob::kByteOrderMark);
  const uint32_t version = swapped ? host::byteswap_scalar(h.version) : h.version;
  return why + " (format " + std::to_string(version) + "; this spinhash reads format " +
         std::to_string(blob::kFormatVersion) + ": rebuild it from its meshes with `spinhash build`)";
}

}  // namespace

bool load_database(const std::string& path, DatabaseFile* out, std::string* error) {
  if (!host::read_file(path, &out->bytes, error)) return false;
  if (out->bytes.empty()) {
    *error = path + ": empty file, not a database";
    return false;
  }
  Status s = Database::open(out->bytes.data(), out->bytes.size(), &out->db);
  if (s != Status::kOk) {
    *error = path + ": " + refusal(out->bytes, s);
    return false;
  }
  return true;
}

}  // namespace spinhash::pipeline
