#include "blob/file_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace spinhash {
namespace host {
namespace {

constexpr mode_t kNewFileMode = 0644;  // mkstemp creates 0600; blobs are meant to be shared

std::string describe(const std::string& what, const std::string& path, int err) {
  return what + " '" + path + "': " + std::strerror(err);
}

// Closes the descriptor on every path out of a function.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  int release() {
    const int f = fd;
    fd = -1;
    return f;
  }
};

bool read_all(int fd, uint8_t* dst, size_t size) {
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, dst + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;  // error, or the file shrank under us
    done += static_cast<size_t>(n);
  }
  return true;
}

bool write_all(int fd, const uint8_t* src, size_t size) {
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, src + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

std::string directory_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0u ? "/" : path.substr(0, slash);
}

std::string base_name_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1u);
}

// Makes the rename itself durable; some file systems refuse, which is harmless.
void sync_directory(const std::string& dir) {
  Fd d;
  d.fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (d.fd >= 0) (void)::fsync(d.fd);
}

// Writes, flushes and closes the temporary; false leaves errno set.
bool fill_temporary(int fd, const void* data, size_t size, mode_t mode) {
  Fd f;
  f.fd = fd;
  if (::fchmod(f.fd, mode) != 0) return false;
  if (!write_all(f.fd, static_cast<const uint8_t*>(data), size)) return false;
  if (::fsync(f.fd) != 0) return false;
  return ::close(f.release()) == 0;
}

// Opens a regular file no larger than max_bytes; its size in *size.
bool open_regular(const std::string& path, uint64_t max_bytes, Fd* f, uint64_t* size, std::string* error) {
  f->fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (f->fd < 0) {
    *error = describe("cannot open", path, errno);
    return false;
  }
  struct stat st {};
  if (::fstat(f->fd, &st) != 0) {
    *error = describe("cannot stat", path, errno);
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    *error = "'" + path + "' is not a regular file";
    return false;
  }
  *size = static_cast<uint64_t>(st.st_size);
  if (*size > max_bytes || *size > SIZE_MAX) {
    *error = "'" + path + "' is larger than the limit of " +
             std::to_string(std::min<uint64_t>(max_bytes, SIZE_MAX)) + " bytes";
    return false;
  }
  return true;
}

// All of standard input, up to max_bytes.
bool read_stdin(uint64_t max_bytes, std::string* out, std::string* error) {
  constexpr size_t kChunk = size_t{1} << 16;
  char chunk[kChunk];
  for (;;) {
    const ssize_t n = ::read(STDIN_FILENO, chunk, kChunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      *error = describe("cannot read", "standard input", errno);
      return false;
    }
    if (n == 0) return true;
    if (out->size() + static_cast<size_t>(n) > max_bytes) {
      *error = "standard input is larger than the limit of " + std::to_string(max_bytes) + " bytes";
      return false;
    }
    out->append(chunk, static_cast<size_t>(n));
  }
}

}  // namespace

bool read_file(const std::string& path, AlignedBytes* out, std::string* error) {
  *out = AlignedBytes();
  error->clear();
  Fd f;
  uint64_t size = 0;
  if (!open_regular(path, UINT64_MAX, &f, &size, error)) return false;
  AlignedBytes bytes(static_cast<size_t>(size));
  if (!read_all(f.fd, bytes.data(), bytes.size())) {
    *error = describe("cannot read", path, errno != 0 ? errno : EIO);
    return false;
  }
  *out = std::move(bytes);
  return true;
}

bool read_file(const std::string& path, uint64_t max_bytes, std::string* out, std::string* error) {
  out->clear();
  error->clear();
  bool ok = false;
  if (path == kStdinPath) {
    ok = read_stdin(max_bytes, out, error);
  } else {
    Fd f;
    uint64_t size = 0;
    if (open_regular(path, max_bytes, &f, &size, error)) {
      out->resize(static_cast<size_t>(size));
      ok = read_all(f.fd, reinterpret_cast<uint8_t*>(out->data()), out->size());
      if (!ok) *error = describe("cannot read", path, errno != 0 ? errno : EIO);
    }
  }
  if (!ok) out->clear();
  return ok;
}

bool write_file_atomically(const std::string& path, const std::vector<uint8_t>& bytes, std::string* error) {
  return write_file_atomically(path, bytes.data(), bytes.size(), error);
}

bool write_file_atomically(const std::string& path, const void* data, size_t size, std::string* error) {
  error->clear();
  const std::string dir = directory_of(path);
  const std::string base = base_name_of(path);
  if (base.empty()) {
    *error = "'" + path + "' names a directory, not a file";
    return false;
  }
  mode_t mode = kNewFileMode;
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) {
    mode = existing.st_mode & 07777;  // replacing a file keeps its permissions
  }
  std::string temp = dir + "/." + base + ".tmp.XXXXXX";
  const int fd = ::mkstemp(&temp[0]);
  if (fd < 0) {
    *error = describe("cannot create a temporary file in directory", dir, errno);
    return false;
  }
  errno = 0;
  if (!fill_temporary(fd, data, size, mode)) {
    const int err = errno != 0 ? errno : EIO;
    ::unlink(temp.c_str());
    *error = describe("cannot write", temp, err);
    return false;
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    *error = describe("cannot replace", path, err);
    return false;
  }
  sync_directory(dir);
  return true;
}

}  // namespace host
}  // namespace spinhash
