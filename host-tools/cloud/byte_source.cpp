#include "cloud/byte_source.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "cloud/cloud_error.hpp"

namespace spinhash::host {
namespace {

class MemorySource : public ByteSource {
 public:
  explicit MemorySource(const std::string& bytes) : bytes_(bytes) {}
  uint64_t size() const override { return bytes_.size(); }
  void read_at(uint64_t offset, void* out, size_t n) override {
    if (!holds(offset, n))
      throw CloudError("file ends at byte " + std::to_string(bytes_.size()) + ", before " +
                       std::to_string(n) + " bytes at " + std::to_string(offset));
    std::memcpy(out, bytes_.data() + offset, n);
  }

 private:
  const std::string& bytes_;
};

// Keeps its bytes; the base reads them.
class OwnedMemorySource final : public MemorySource {
 public:
  explicit OwnedMemorySource(std::unique_ptr<std::string> bytes)
      : MemorySource(*bytes), owned_(std::move(bytes)) {}

 private:
  std::unique_ptr<std::string> owned_;
};

class FileSource final : public ByteSource {
 public:
  FileSource(std::FILE* f, uint64_t size) : f_(f), size_(size) {}
  ~FileSource() override { std::fclose(f_); }
  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;
  uint64_t size() const override { return size_; }
  void read_at(uint64_t offset, void* out, size_t n) override {
    if (!holds(offset, n))
      throw CloudError("file ends at byte " + std::to_string(size_) + ", before " + std::to_string(n) +
                       " bytes at " + std::to_string(offset));
    if (offset != position_ && fseeko(f_, static_cast<off_t>(offset), SEEK_SET) != 0)
      throw CloudError("cannot seek to byte " + std::to_string(offset));
    if (std::fread(out, 1, n, f_) != n) throw CloudError("cannot read " + std::to_string(n) + " bytes");
    position_ = offset + n;
  }

 private:
  std::FILE* f_;
  uint64_t size_;
  uint64_t position_ = 0;
};

}  // namespace

std::unique_ptr<ByteSource> memory_source(const std::string& bytes) {
  return std::make_unique<MemorySource>(bytes);
}

std::unique_ptr<ByteSource> owned_memory_source(std::string bytes) {
  return std::make_unique<OwnedMemorySource>(std::make_unique<std::string>(std::move(bytes)));
}

std::unique_ptr<ByteSource> file_source(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw CloudError("file not found: " + path);
  if (!std::filesystem::is_regular_file(path, ec)) throw CloudError("not a regular file: " + path);
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw CloudError("cannot stat " + path + ": " + ec.message());
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw CloudError("cannot read " + path);
  return std::make_unique<FileSource>(f, static_cast<uint64_t>(size));
}

}  // namespace spinhash::host
