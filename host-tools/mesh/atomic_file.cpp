#include "mesh/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <unistd.h>

namespace spinhash::host {
namespace {

std::string errno_text() { return std::strerror(errno); }

bool fail(std::string* error, const std::string& message, const std::string& tmp) {
  if (error) *error = message;
  std::remove(tmp.c_str());
  return false;
}

}  // namespace

bool write_file_atomically(const std::string& path, const std::string& bytes,
                           std::string* error) {
  if (path.empty()) {
    if (error) *error = "empty output path";
    return false;
  }
  const std::string tmp = path + ".tmp";
  std::FILE* file = std::fopen(tmp.c_str(), "wb");
  if (file == nullptr) {
    if (error) *error = "cannot create " + tmp + ": " + errno_text();
    return false;
  }
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  // fsync so a crash after rename cannot expose an empty file.
  const bool flushed = std::fflush(file) == 0 && ::fsync(fileno(file)) == 0;
  const bool closed = std::fclose(file) == 0;
  if (!written || !flushed || !closed) {
    return fail(error, "cannot write " + tmp + ": " + errno_text(), tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    return fail(error, "cannot rename " + tmp + " to " + path + ": " + errno_text(), tmp);
  }
  return true;
}

}  // namespace spinhash::host
