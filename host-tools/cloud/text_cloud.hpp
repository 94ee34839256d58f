// Plain-text point clouds (docs/cli.md, "Text clouds"): one point per line;
// '#' starts a comment; blank lines skipped. The first line fixes the
// separator of the whole file (';', tab, ',' or spaces, in that order of
// precedence); a decimal comma is read only where ';' or tab separates. A
// first line with no number in it is a header: x, y and z are the columns
// named so (any case; CloudCompare's leading "//" allowed), other columns
// ignored. Without a header, the first three columns are x y z.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace spinhash::host {

// The rules a line at a time (cloud/point_source.cpp reads files in chunks).
class TextCloudParser {
 public:
  // Takes the next line (without its '\n'). True when it was read: *has_point
  // says whether it held a point (written to point[0..3)); false with
  // *error ("text cloud line N: ...") otherwise.
  bool line(std::string_view line, double point[3], bool* has_point, std::string* error);

 private:
  bool first_ = true;
  char separator_ = ' ';  // a text::Separator, chosen by the first line
  std::size_t column_[3] = {0, 1, 2};
  std::size_t number_ = 0;
  std::vector<std::string_view> fields_;
};

constexpr const char* kTextBinaryMessage = "binary data in a text point cloud (neither PLY nor x y z text)";
constexpr const char* kTextEmptyMessage = "no points in the text point cloud";

}  // namespace spinhash::host
