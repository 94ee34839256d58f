#include "memory_database.hpp"

#include <chrono>

#include "blob/blob_writer.hpp"

namespace spinhash::experiment {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::unique_ptr<MemoryDatabase> build_memory_database(const std::vector<host::ModelCloud>& clouds,
                                                      const host::BuildOptions& options, bool keep_content,
                                                      std::string* error) {
  auto out = std::make_unique<MemoryDatabase>();
  auto start = std::chrono::steady_clock::now();
  if (!host::build_database(clouds, options, &out->content, &out->report, error)) return nullptr;
  out->build_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  if (!host::open_content(out->content, &out->bytes, &out->db, error)) return nullptr;
  out->serialize_seconds = seconds_since(start);
  out->blob_bytes = out->bytes.size();
  if (!keep_content) out->content = host::BlobContent{};
  return out;
}

}  // namespace spinhash::experiment
