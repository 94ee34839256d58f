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

// Next line at *pos without its comment and line end; false at the end of the text.
bool next_line(const std::string& text, std::size_t* pos, std::string_view* line) {
  if (*pos >= text.size()) return false;
  std::size_t end = text.find('\n', *pos);
  if (end == std::string::npos) end = text.size();
  *line = std::string_view(text).substr(*pos, end - *pos);
  *line = line->substr(0, line->find('#'));
  *pos = end + 1;
  return true;
}

bool blank(std::string_view line) { return line.find_first_not_of(" \t\r\v\f") == std::string_view::npos; }

}  // namespace

bool read_text_cloud(const std::string& text, std::vector<double>* xyz, std::string* error) {
  xyz->clear();
  if (text.find('\0') != std::string::npos) {
    if (error) *error = "binary data in a text point cloud (neither PLY nor x y z text)";
    return false;
  }
  bool first = true;
  text::Separator sep = text::Separator::kSpaces;
  std::size_t column[kAxes] = {0, 1, 2};
  std::vector<std::string_view> fields;
  std::string why;
  std::size_t number = 0;
  std::string_view line;
  for (std::size_t pos = 0; next_line(text, &pos, &line);) {
    ++number;
    if (blank(line)) continue;
    if (first) {
      const std::size_t start = line.find_first_not_of(" \t");
      if (line.substr(start, 2) == "//") line.remove_prefix(start + 2);  // CloudCompare's header
      sep = text::choose_separator(line);
    }
    if (!text::split_fields(line, sep, &fields, &why)) return fail(error, number, why);
    if (first && (first = false, is_header(fields, sep))) {
      if (!header_columns(fields, column, &why)) return fail(error, number, why);
      continue;
    }
    double point[kAxes];
    for (int a = 0; a < kAxes; ++a) {
      if (column[a] >= fields.size()) {
        return fail(error, number,
                    "fewer values than the columns x y z need (separator " +
                        std::string(text::separator_name(sep)) + ")");
      }
      if (!text::parse_field(fields[column[a]], sep, &point[a], &why)) return fail(error, number, why);
    }
    xyz->insert(xyz->end(), point, point + kAxes);
  }
  if (xyz->empty()) {
    if (error) *error = "no points in the text point cloud";
    return false;
  }
  return true;
}

}  // namespace spinhash::host
