// Blob files on disk: read_file round trip into aligned memory, and
// write_file_atomically never leaving a damaged or half-written target.
#include <dirent.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <doctest/doctest.h>

#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "blob/blob_writer.hpp"
#include "blob/file_io.hpp"
#include "db/tiny_blob.hpp"
#include "spinhash/database.hpp"

namespace host = spinhash::host;

namespace {

// A fresh directory under TMPDIR, removed (with its plain files) at scope exit.
struct TempDir {
  std::string path;
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base != nullptr ? base : "/tmp") + "/spinhash_blob_XXXXXX";
    REQUIRE(::mkdtemp(&tmpl[0]) != nullptr);
    path = tmpl;
  }
  ~TempDir() {
    for (const std::string& name : entries()) {
      const std::string p = path + "/" + name;
      if (::unlink(p.c_str()) != 0) ::rmdir(p.c_str());
    }
    ::rmdir(path.c_str());
  }
  std::set<std::string> entries() const {
    std::set<std::string> names;
    DIR* d = ::opendir(path.c_str());
    if (d == nullptr) return names;
    while (const dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") names.insert(n);
    }
    ::closedir(d);
    return names;
  }
};

std::vector<uint8_t> tiny_blob_bytes() {
  std::vector<uint8_t> bytes;
  std::string error;
  REQUIRE(
      host::serialize_blob(host::make_tiny_blob_content(2, 10, 3), host::ByteOrder::kNative, &bytes, &error));
  return bytes;
}

std::vector<uint8_t> contents_of(const std::string& path) {
  host::AlignedBytes bytes;
  std::string error;
  REQUIRE_MESSAGE(host::read_file(path, &bytes, &error), error);
  return std::vector<uint8_t>(bytes.data(), bytes.data() + bytes.size());
}

// Lowers the file-size limit for the scope, so writes fail part-way (EFBIG).
struct FileSizeLimit {
  rlimit saved{};
  void (*saved_handler)(int) = nullptr;
  explicit FileSizeLimit(rlim_t bytes) {
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &saved) == 0);
    saved_handler = ::signal(SIGXFSZ, SIG_IGN);  // get EFBIG instead of being killed
    rlimit lower = saved;
    lower.rlim_cur = bytes;
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &lower) == 0);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved);
    ::signal(SIGXFSZ, saved_handler);
  }
};

}  // namespace

TEST_CASE("a blob written atomically reads back aligned, equal and valid") {
  TempDir dir;
  const std::string path = dir.path + "/db.shdb";
  const std::vector<uint8_t> bytes = tiny_blob_bytes();
  std::string error = "stale";
  REQUIRE(host::write_file_atomically(path, bytes, &error));
  CHECK(error.empty());
  host::AlignedBytes read;
  REQUIRE(host::read_file(path, &read, &error));
  CHECK(reinterpret_cast<uintptr_t>(read.data()) % spinhash::kBufferAlignment == 0u);
  REQUIRE(read.size() == bytes.size());
  CHECK(std::vector<uint8_t>(read.data(), read.data() + read.size()) == bytes);
  spinhash::Database db;
  CHECK(spinhash::Database::open(read.data(), read.size(), &db) == spinhash::Status::kOk);
  CHECK(dir.entries() == std::set<std::string>{"db.shdb"});
}

TEST_CASE("replacing a file keeps its permissions") {
  TempDir dir;
  const std::string path = dir.path + "/db.shdb";
  std::string error;
  REQUIRE(host::write_file_atomically(path, {1, 2, 3}, &error));
  REQUIRE(::chmod(path.c_str(), 0640) == 0);
  REQUIRE(host::write_file_atomically(path, {4, 5}, &error));
  CHECK(contents_of(path) == std::vector<uint8_t>{4, 5});
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0640u);
}

TEST_CASE("a directory that does not exist fails with a clear error") {
  TempDir dir;
  const std::string missing = dir.path + "/no/such/dir";
  std::string error;
  CHECK_FALSE(host::write_file_atomically(missing + "/db.shdb", {1, 2, 3}, &error));
  CHECK(error.find(missing) != std::string::npos);
  CHECK(error.find("temporary") != std::string::npos);
  CHECK(dir.entries().empty());
}

TEST_CASE("a directory as the target is left alone and no temporary remains") {
  TempDir dir;
  const std::string target = dir.path + "/adir";
  REQUIRE(::mkdir(target.c_str(), 0755) == 0);
  std::string error;
  CHECK_FALSE(host::write_file_atomically(target, {1, 2, 3}, &error));
  CHECK_FALSE(error.empty());
  struct stat st {};
  REQUIRE(::stat(target.c_str(), &st) == 0);
  CHECK(S_ISDIR(st.st_mode));
  CHECK(dir.entries() == std::set<std::string>{"adir"});
  CHECK_FALSE(host::write_file_atomically(dir.path + "/", {1}, &error));
}

TEST_CASE("a write failing part-way never clobbers the existing good file") {
  TempDir dir;
  const std::string path = dir.path + "/db.shdb";
  const std::vector<uint8_t> good = tiny_blob_bytes();
  std::string error;
  REQUIRE(host::write_file_atomically(path, good, &error));
  const std::vector<uint8_t> bigger(good.size() * 4, 0xAB);
  {
    FileSizeLimit limit(good.size() / 2);
    CHECK_FALSE(host::write_file_atomically(path, bigger, &error));
  }
  CHECK(error.find("cannot write") != std::string::npos);
  CHECK(contents_of(path) == good);
  CHECK(dir.entries() == std::set<std::string>{"db.shdb"});
}

TEST_CASE("a temporary that cannot be created never clobbers the existing good file") {
  TempDir dir;
  // The longest legal file name: its temporary's name is too long to create.
  const std::string path = dir.path + "/" + std::string(250, 'n');
  const std::vector<uint8_t> good = {9, 8, 7};
  std::string error;
  REQUIRE(host::write_file_atomically(dir.path + "/seed", good, &error));
  REQUIRE(::rename((dir.path + "/seed").c_str(), path.c_str()) == 0);
  CHECK_FALSE(host::write_file_atomically(path, {1, 2, 3, 4}, &error));
  CHECK_FALSE(error.empty());
  CHECK(contents_of(path) == good);
  CHECK(dir.entries().size() == 1u);
}

TEST_CASE("read_file reports missing files and non-files") {
  TempDir dir;
  host::AlignedBytes out = host::AlignedBytes::copy_of(std::vector<uint8_t>{1, 2});
  std::string error;
  CHECK_FALSE(host::read_file(dir.path + "/missing.shdb", &out, &error));
  CHECK(out.empty());
  CHECK(error.find("missing.shdb") != std::string::npos);
  CHECK_FALSE(host::read_file(dir.path, &out, &error));
  CHECK(error.find("not a regular file") != std::string::npos);
  REQUIRE(host::write_file_atomically(dir.path + "/empty", {}, &error));
  CHECK(host::read_file(dir.path + "/empty", &out, &error));
  CHECK(out.empty());
}
