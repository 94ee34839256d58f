#include "cloud/text_cloud.hpp"

#include <cctype>
#include <cstddef>
#include <string_view>

#include "cloud/text_fields.hpp"

namespace spinhash::host {
namespace {

constexpr int kAxes = 3;
constexpr const char* kAxisNames[kAxes] = {"x", "y", "z"};

bool fail(std::string* error, std::size_t line, const std::string& message) {
  if (error) *error = "text cloud line " + std::to_string(line) + ": " + message;
  return false;
}

bool names_axis(std::string_view field, int axis) {
  return field.size() == 1 && std::tolower(static_cast<unsigned char>(field[0])) == kAxisNames[axis][0];
}

bool is_header(const std::vector<std::string_view>& fields, text::Separator s) {
  for (std::string_view f : fields) {
    double ignored = 0.0;
    if (text::parse_field(f, s, &ignored, nullptr)) return false;
  }
  return true;
}

// The column of each axis, from the header's names.
bool header_columns(const std::vector<std::string_view>& fields, std::size_t column[kAxes],
                    std::string* why) {
  bool found[kAxes] = {false, false, false};
  for (std::size_t c = 0; c < fields.size(); ++c) {
    for (int a = 0; a < kAxes; ++a) {
      if (!names_axis(fields[c], a)) continue;
      if (found[a]) {
        *why = std::string("header names column ") + kAxisNames[a] + " twice";
        return false;
      }
      found[a] = true;
      column[a] = c;
    }
  }
  if (!found[0] || !found[1] || !found[2]) {
    *why = "the header has no x, y and z columns (names are x y z, any case)";
    return false;
  }
  return true;
}

// Next line at *pos without its line end; false at the end of the text.
bool blank(std::string_view line) { return line.find_first_not_of(" \t\r\v\f") == std::string_view::npos; }

}  // namespace

bool TextCloudParser::line(std::string_view line, double point[kAxes], bool* has_point, std::string* error) {
  *has_point = false;
  ++number_;
  if (line.find('\0') != std::string_view::npos) {
    if (error) *error = kTextBinaryMessage;
    return false;
  }
  line = line.substr(0, line.find('#'));
  if (blank(line)) return true;
  auto sep = static_cast<text::Separator>(separator_);
  if (first_) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (line.substr(start, 2) == "//") line.remove_prefix(start + 2);  // CloudCompare's header
    sep = text::choose_separator(line);
    separator_ = static_cast<char>(sep);
  }
  std::string why;
  if (!text::split_fields(line, sep, &fields_, &why)) return fail(error, number_, why);
  if (first_ && (first_ = false, is_header(fields_, sep))) {
    if (!header_columns(fields_, column_, &why)) return fail(error, number_, why);
    return true;
  }
  for (int a = 0; a < kAxes; ++a) {
    if (column_[a] >= fields_.size()) {
      return fail(error, number_,
                  "fewer values than the columns x y z need (separator " +
                      std::string(text::separator_name(sep)) + ")");
    }
    if (!text::parse_field(fields_[column_[a]], sep, &point[a], &why)) return fail(error, number_, why);
  }
  *has_point = true;
  return true;
}

}  // namespace spinhash::host
