#include "cloud/cloud_reader.hpp"

#include "cloud/format_sniff.hpp"
#include "cloud/las_reader.hpp"
#include "cloud/ply_body.hpp"
#include "cloud/ply_header.hpp"
#include "cloud/text_cloud.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace spinhash::host {
namespace {

// All of standard input, binary; false past max_bytes.
bool read_stdin_bytes(uint64_t max_bytes, std::string* bytes, std::string* error) {
  constexpr std::size_t kChunk = 1 << 16;
  bytes->clear();
  char chunk[kChunk];
  for (std::size_t got; (got = std::fread(chunk, 1, kChunk, stdin)) > 0;) {
    if (bytes->size() + got > max_bytes) {
      if (error)
        *error =
            std::string(kStdinName) + " is larger than the limit of " + std::to_string(max_bytes) + " bytes";
      return false;
    }
    bytes->append(chunk, got);
  }
  if (std::ferror(stdin)) {
    if (error) *error = std::string("cannot read ") + kStdinName;
    return false;
  }
  return true;
}

}  // namespace

std::string cloud_name(const std::string& path) {
  return path == kStdinPath ? kStdinName : std::filesystem::path(path).stem().string();
}

bool parse_cloud(const std::string& bytes, std::vector<double>* xyz, std::string* error) {
  if (xyz == nullptr) {
    if (error) *error = "parse_cloud: null output";
    return false;
  }
  xyz->clear();
  try {
    bool ok = false;
    const std::string foreign = foreign_cloud_format(bytes);
    if (!foreign.empty()) {
      if (error) *error = "not a point cloud this reader takes: " + foreign;
    } else if (is_las(bytes)) {
      LasCloud las;
      ok = parse_las(bytes, &las, error);
      if (ok) *xyz = std::move(las.xyz);
    } else if (is_ply(bytes)) {
      ply::Header header;
      ok = ply::parse_header(bytes, &header, error) && ply::read_body(bytes, header, xyz, error);
    } else {
      ok = read_text_cloud(bytes, xyz, error);
    }
    if (!ok) xyz->clear();  // no partial clouds
    return ok;
  } catch (const std::exception& e) {
    xyz->clear();
    if (error) *error = e.what();
    return false;
  }
}

bool read_file_bytes(const std::string& path, uint64_t max_bytes, std::string* bytes, std::string* error) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    if (error) *error = "file not found: " + path;
    return false;
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    if (error) *error = "not a regular file: " + path;
    return false;
  }
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) {
    if (error) *error = "cannot stat " + path + ": " + ec.message();
    return false;
  }
  if (size > max_bytes) {
    if (error) *error = path + " is larger than the limit of " + std::to_string(max_bytes) + " bytes";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  bytes->assign(static_cast<std::size_t>(size), '\0');
  if (!in || !in.read(bytes->data(), static_cast<std::streamsize>(size))) {
    if (error) *error = "cannot read " + path;
    return false;
  }
  return true;
}

bool read_cloud(const std::string& path, std::vector<double>* xyz, std::string* error) {
  if (xyz == nullptr) {
    if (error) *error = "read_cloud: null output";
    return false;
  }
  xyz->clear();
  try {
    std::string bytes;
    std::string why;
    const bool from_stdin = path == kStdinPath;
    if (from_stdin ? !read_stdin_bytes(kMaxCloudFileBytes, &bytes, error)
                   : !read_file_bytes(path, kMaxCloudFileBytes, &bytes, error))
      return false;
    if (parse_cloud(bytes, xyz, &why)) return true;
    if (error) *error = (from_stdin ? std::string(kStdinName) : path) + ": " + why;
  } catch (const std::exception& e) {
    if (error) *error = path + ": " + e.what();
  }
  xyz->clear();
  return false;
}

}  // namespace spinhash::host
