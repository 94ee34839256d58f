// Random access to the bytes of a point-cloud file, from memory or from
// disk, so that the LAS and LAZ readers read only what they need (a header,
// a chunk) and memory does not grow with the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace spinhash::host {

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual uint64_t size() const = 0;
  // Reads exactly n bytes at offset; throws CloudError (cloud/cloud_error.hpp) when
  // they are not all in the file.
  virtual void read_at(uint64_t offset, void* out, size_t n) = 0;
  // True when [offset, offset + n) lies inside the data.
  bool holds(uint64_t offset, uint64_t n) const { return offset <= size() && n <= size() - offset; }
};

// Over bytes the caller keeps alive.
std::unique_ptr<ByteSource> memory_source(const std::string& bytes);
// Over bytes it keeps (standard input, read whole).
std::unique_ptr<ByteSource> owned_memory_source(std::string bytes);
// Over a regular file; throws CloudError when it cannot be opened.
std::unique_ptr<ByteSource> file_source(const std::string& path);

}  // namespace spinhash::host
