// Whole-file reads (the one reader of whole files on the host: databases,
// clouds from standard input, meshes, stored survey results) and
// crash-safe replacement of a file (POSIX: the blob tools run on Linux
// hosts and Linux targets).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"

namespace spinhash {
namespace host {

// The path that means standard input.
constexpr const char* kStdinPath = "-";

// Reads the whole regular file into 64-byte-aligned memory (Database::open
// requires it). On failure *out is emptied and *error says why.
bool read_file(const std::string& path, AlignedBytes* out, std::string* error);
// Reads the whole regular file, or all of standard input for "-", up to
// max_bytes. On failure *out is emptied and *error says why, naming the file.
bool read_file(const std::string& path, uint64_t max_bytes, std::string* out, std::string* error);

// Writes to a temporary file next to `path`, flushes it to disk, then renames
// it over `path`: readers see the old file or the new one, never a mix. On
// failure the temporary is removed and an existing `path` is left untouched.
bool write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes, std::string* error);
bool write_file_atomically(const std::string& path, const void* data, size_t size, std::string* error);

}  // namespace host
}  // namespace spinhash
