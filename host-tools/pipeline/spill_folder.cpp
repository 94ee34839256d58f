#include "pipeline/spill_folder.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>

namespace spinhash::pipeline {
namespace {

namespace fs = std::filesystem;

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}

std::set<std::string>& registry() {
  static std::set<std::string> folders;
  return folders;
}

bool& closing() {  // after remove_own_spill_folders: no new folder (the process is exiting)
  static bool c = false;
  return c;
}

// Writers may still add files while a folder is removed: a few passes.
constexpr int kRemovePasses = 20;
constexpr useconds_t kRemovePauseMicroseconds = 10000;

// The process id a spill folder's name carries; 0 when it carries none.
long owner_pid(const std::string& name) {
  const std::string prefix = kSpillFolderPrefix;
  if (name.compare(0, prefix.size(), prefix) != 0) return 0;
  const char* start = name.c_str() + prefix.size();
  char* end = nullptr;
  const long pid = std::strtol(start, &end, 10);
  return end != start && *end == '-' && pid > 0 ? pid : 0;
}

bool running(long pid) { return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM; }

uint64_t folder_bytes(const fs::path& dir) {
  uint64_t bytes = 0;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir, ec)) {
    const uintmax_t n = e.is_regular_file(ec) ? e.file_size(ec) : 0;
    if (!ec) bytes += n;
  }
  return bytes;
}

}  // namespace

std::string make_spill_folder() {
  std::error_code ec;
  const fs::path temp = fs::temp_directory_path(ec);
  std::string pattern =
      ((ec ? fs::path("/tmp") : temp) / (kSpillFolderPrefix + std::to_string(::getpid()) + "-XXXXXX"))
          .string();
  std::lock_guard<std::mutex> lock(registry_mutex());
  if (closing()) throw std::runtime_error("interrupted: no new temporary folder");
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot make a temporary folder " + pattern);
  registry().insert(pattern);
  return pattern;
}

void remove_spill_folder(const std::string& path) {
  std::error_code ec;
  fs::remove_all(path, ec);
  std::lock_guard<std::mutex> lock(registry_mutex());
  registry().erase(path);
}

size_t remove_own_spill_folders() {
  std::lock_guard<std::mutex> lock(registry_mutex());
  closing() = true;
  size_t n = 0;
  for (const std::string& path : registry()) {
    bool removed = false;
    for (int pass = 0; pass < kRemovePasses; ++pass) {
      std::error_code ec;
      removed = fs::remove_all(path, ec) > 0 || removed;
      if (!fs::exists(path, ec)) break;
      ::usleep(kRemovePauseMicroseconds);
    }
    n += removed ? 1u : 0u;
  }
  registry().clear();
  return n;
}

StaleSpill remove_stale_spill_folders() {
  StaleSpill s;
  std::error_code ec;
  const fs::path temp = fs::temp_directory_path(ec);
  if (ec) return s;
  for (const fs::directory_entry& e : fs::directory_iterator(temp, ec)) {
    const long pid = owner_pid(e.path().filename().string());
    std::error_code ec2;
    if (pid == 0 || running(pid) || !e.is_directory(ec2)) continue;
    const uint64_t bytes = folder_bytes(e.path());
    if (fs::remove_all(e.path(), ec2) > 0 && !ec2) {
      ++s.folders;
      s.bytes += bytes;
    }
  }
  return s;
}

void report_stale_spill_folders(const char* command) {
  const StaleSpill stale = remove_stale_spill_folders();
  if (stale.folders > 0)
    std::fprintf(stderr, "spinhash %s: removed %zu temporary folder%s (%.1f MB) left by interrupted runs\n",
                 command, stale.folders, stale.folders == 1 ? "" : "s",
                 static_cast<double>(stale.bytes) / 1e6);
}

}  // namespace spinhash::pipeline
