#include "cloud/text_cloud.hpp"

#include <charconv>
#include <cstddef>
#include <string_view>

namespace spinhash::host {
namespace {

constexpr int kAxes = 3;
constexpr std::size_t kMaxQuotedChars = 40;  // of a bad token, in messages

bool is_separator(char ch) {
  return ch == ' ' || ch == '\t' || ch == '\r' || ch == ',' || ch == '\v' || ch == '\f';
}

// Splits the first `wanted` tokens of a line.
int split_tokens(std::string_view line, std::string_view* tokens, int wanted) {
  int found = 0;
  std::size_t pos = 0;
  while (found < wanted) {
    while (pos < line.size() && is_separator(line[pos])) ++pos;
    if (pos >= line.size()) break;
    const std::size_t start = pos;
    while (pos < line.size() && !is_separator(line[pos])) ++pos;
    tokens[found++] = line.substr(start, pos - start);
  }
  return found;
}

bool parse_number(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, *value);
  return !token.empty() && result.ec == std::errc() && result.ptr == end;
}

bool fail(std::string* error, std::size_t line, const std::string& message) {
  if (error) *error = "text cloud line " + std::to_string(line) + ": " + message;
  return false;
}

}  // namespace

bool read_text_cloud(const std::string& text, std::vector<double>* xyz, std::string* error) {
  xyz->clear();
  if (text.find('\0') != std::string::npos) {
    if (error) *error = "binary data in a text point cloud (neither PLY nor x y z text)";
    return false;
  }
  bool may_skip_header = true;
  std::size_t line_number = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line = std::string_view(text).substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    line = line.substr(0, line.find('#'));
    std::string_view tokens[kAxes];
    const int found = split_tokens(line, tokens, kAxes);
    if (found == 0) continue;
    double point[kAxes] = {0.0, 0.0, 0.0};
    bool numeric = found == kAxes;
    for (int k = 0; k < found && numeric; ++k) numeric = parse_number(tokens[k], &point[k]);
    if (!numeric && may_skip_header && !parse_number(tokens[0], &point[0])) {
      may_skip_header = false;  // a column-name line, once, before any point
      continue;
    }
    if (found < kAxes) return fail(error, line_number, "fewer than 3 values");
    if (!numeric) {
      return fail(error, line_number,
                  "not a number in '" + std::string(line.substr(0, kMaxQuotedChars)) + "'");
    }
    may_skip_header = false;
    xyz->insert(xyz->end(), point, point + kAxes);
  }
  if (xyz->empty()) {
    if (error) *error = "no points in the text point cloud";
    return false;
  }
  return true;
}

}  // namespace spinhash::host
