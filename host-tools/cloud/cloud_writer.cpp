#include "cloud/cloud_writer.hpp"

#include <cctype>

#include "cloud/las_writer.hpp"

#include "blob/file_io.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>

namespace spinhash::host {
namespace {

constexpr int kAxes = 3;
constexpr std::size_t kLineBufferBytes = 128;

void append_double_le(std::string* out, double value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int shift = 0; shift < 64; shift += 8) out->push_back(static_cast<char>(bits >> shift));
}

std::string ply_bytes(const std::vector<double>& xyz, bool binary) {
  const std::size_t points = xyz.size() / kAxes;
  std::string out = std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") +
                    " 1.0\ncomment spinhash point cloud\nelement vertex " + std::to_string(points) +
                    "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  if (binary) {
    out.reserve(out.size() + points * kAxes * sizeof(double));
    for (double v : xyz) append_double_le(&out, v);
    return out;
  }
  char line[kLineBufferBytes];
  for (std::size_t i = 0; i < points; ++i) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", xyz[kAxes * i], xyz[kAxes * i + 1],
                  xyz[kAxes * i + 2]);
    out += line;
  }
  return out;
}

}  // namespace

bool write_ply(const std::string& path, const std::vector<double>& xyz, bool binary, std::string* error) {
  if (xyz.size() % kAxes != 0) {
    if (error) *error = "cannot write " + path + ": coordinate count is not a multiple of 3";
    return false;
  }
  try {
    const std::string bytes = ply_bytes(xyz, binary);
    return write_file_atomically(path, bytes.data(), bytes.size(), error);
  } catch (const std::exception& e) {
    if (error) *error = "cannot write " + path + ": " + e.what();
    return false;
  }
}

bool write_pose(const std::string& path, const Eigen::Matrix4d& pose, std::string* error) {
  std::string text;
  char line[kLineBufferBytes];
  for (int r = 0; r < 4; ++r) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g\n", pose(r, 0), pose(r, 1), pose(r, 2),
                  pose(r, 3));
    text += line;
  }
  return write_file_atomically(path, text.data(), text.size(), error);
}

CloudFormat cloud_format_for(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == "ply" ? CloudFormat::kPly : ext == "las" ? CloudFormat::kLas : CloudFormat::kUnknown;
}

bool write_cloud(const std::string& path, const std::vector<double>& xyz,
                 const std::vector<uint8_t>& classification, bool ascii, std::string* error) {
  switch (cloud_format_for(path)) {
    case CloudFormat::kPly: return write_ply(path, xyz, !ascii, error);
    case CloudFormat::kLas: return write_las(path, xyz, classification, error);
    default:
      if (error) *error = path + ": unknown point-cloud extension (write .ply or .las)";
      return false;
  }
}

}  // namespace spinhash::host
