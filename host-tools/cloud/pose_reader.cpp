#include "cloud/cloud_reader.hpp"

#include "blob/file_io.hpp"

#include <charconv>
#include <cmath>
#include <exception>
#include <string_view>

namespace spinhash::host {
namespace {

constexpr uint64_t kMaxPoseFileBytes = 4096;
constexpr int kPoseValues = 16;
// Tolerance on the last row 0 0 0 1 (written exactly; allow hand edits).
constexpr double kLastRowTolerance = 1e-9;

bool is_space(char ch) {
  return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\v' || ch == '\f';
}

bool fail(std::string* why, const std::string& message) {
  *why = message;
  return false;
}

bool parse_pose(const std::string& text, Eigen::Matrix4d* pose, std::string* why) {
  std::size_t pos = 0;
  int count = 0;
  while (true) {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    if (pos >= text.size()) break;
    const std::size_t start = pos;
    while (pos < text.size() && !is_space(text[pos])) ++pos;
    std::string_view token = std::string_view(text).substr(start, pos - start);
    if (count == kPoseValues) return fail(why, "more than 16 numbers");
    if (token.front() == '+') token.remove_prefix(1);
    double value = 0.0;
    const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
    if (result.ec != std::errc() || result.ptr != token.data() + token.size() || !std::isfinite(value)) {
      return fail(why, "'" + std::string(token) + "' is not a finite number");
    }
    (*pose)(count / 4, count % 4) = value;
    ++count;
  }
  if (count != kPoseValues) {
    return fail(why, "expected 16 numbers, found " + std::to_string(count));
  }
  const Eigen::RowVector4d last_row(0.0, 0.0, 0.0, 1.0);
  if ((pose->row(3) - last_row).cwiseAbs().maxCoeff() > kLastRowTolerance) {
    return fail(why, "last row is not 0 0 0 1");
  }
  return true;
}

}  // namespace

bool read_pose(const std::string& path, Eigen::Matrix4d* pose, std::string* error) {
  if (pose == nullptr) {
    if (error) *error = "read_pose: null output";
    return false;
  }
  try {
    std::string text;
    if (!read_file(path, kMaxPoseFileBytes, &text, error)) return false;
    Eigen::Matrix4d parsed;
    std::string why;
    if (!parse_pose(text, &parsed, &why)) {
      if (error) *error = path + ": invalid pose: " + why;
      return false;
    }
    *pose = parsed;
    return true;
  } catch (const std::exception& e) {
    if (error) *error = path + ": " + e.what();
    return false;
  }
}

}  // namespace spinhash::host
