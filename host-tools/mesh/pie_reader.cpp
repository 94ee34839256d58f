#include "mesh/pie_reader.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace spinhash::host {
namespace {

constexpr uint32_t kMinPieVersion = 2, kMaxPieVersion = 4;

struct Line {
  uint32_t number = 0;
  std::vector<std::string> tokens;
  bool keyword() const { return !tokens.empty() && std::isupper(static_cast<unsigned char>(tokens[0][0])); }
};

std::vector<Line> split_lines(std::istream& in) {
  std::vector<Line> lines;
  std::string text;
  uint32_t number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (!text.empty() && text.back() == '\r') text.pop_back();  // CRLF files
    Line l{number, {}};
    std::istringstream s(text);
    for (std::string t; s >> t;) l.tokens.push_back(t);
    if (!l.tokens.empty()) lines.push_back(std::move(l));
  }
  return lines;
}

bool parse_uint(const std::string& t, uint32_t max, uint32_t* out) {
  char* end = nullptr;
  unsigned long v = std::strtoul(t.c_str(), &end, 10);
  if (end == t.c_str() || *end != '\0' || v > max) return false;
  *out = static_cast<uint32_t>(v);
  return true;
}

bool parse_coordinate(const std::string& t, double* out) {
  char* end = nullptr;
  *out = std::strtod(t.c_str(), &end);
  return end != t.c_str() && *end == '\0' && std::isfinite(*out);
}

std::string at(const Line& l, const std::string& what) {
  return "line " + std::to_string(l.number) + ": " + what;
}

// Reads the `count` lines after lines[*i] (a POINTS header) as x y z.
bool read_points(const std::vector<Line>& lines, size_t* i, uint32_t count, Mesh* out, std::string* error) {
  for (uint32_t p = 0; p < count; ++p) {
    if (++*i >= lines.size() || lines[*i].keyword()) {
      *error = at(lines[*i - 1], "expected " + std::to_string(count) + " points");
      return false;
    }
    const Line& l = lines[*i];
    double v[3];
    if (l.tokens.size() < 3 || !parse_coordinate(l.tokens[0], &v[0]) ||
        !parse_coordinate(l.tokens[1], &v[1]) || !parse_coordinate(l.tokens[2], &v[2])) {
      *error = at(l, "a point needs three numbers");
      return false;
    }
    out->add_vertex({v[0], v[1], v[2]});
  }
  return true;
}

// Polygon lines: flags (hex) vertex-count index... [texture data, ignored].
// Fanned from the first vertex (PIE polygons are convex).
bool read_polygons(const std::vector<Line>& lines, size_t* i, uint32_t count, uint32_t first_vertex,
                   uint32_t level_points, Mesh* out, PieInfo* info, std::string* error) {
  for (uint32_t p = 0; p < count; ++p) {
    if (++*i >= lines.size() || lines[*i].keyword()) {
      *error = at(lines[*i - 1], "expected " + std::to_string(count) + " polygons");
      return false;
    }
    const Line& l = lines[*i];
    uint32_t n = 0;
    if (l.tokens.size() < 2 || !parse_uint(l.tokens[1], kMaxPiePolygonVertices, &n) ||
        l.tokens.size() < 2u + n) {
      *error = at(l, "bad polygon (flags, vertex count, indices)");
      return false;
    }
    std::vector<uint32_t> idx(n);
    for (uint32_t k = 0; k < n; ++k)
      if (!parse_uint(l.tokens[2 + k], level_points - 1u, &idx[k]) || level_points == 0) {
        *error = at(l, "polygon index out of range");
        return false;
      }
    for (uint32_t k = 1; k + 1 < n; ++k)
      out->add_triangle(first_vertex + idx[0], first_vertex + idx[k], first_vertex + idx[k + 1]);
    ++info->polygons;
  }
  return true;
}

}  // namespace

bool parse_pie(std::istream& in, Mesh* out, PieInfo* info, std::string* error) {
  *info = PieInfo{};
  out->vertices.clear();
  out->triangles.clear();
  const std::vector<Line> lines = split_lines(in);
  if (lines.empty() || lines[0].tokens.size() < 2 || lines[0].tokens[0] != "PIE" ||
      !parse_uint(lines[0].tokens[1], kMaxPieVersion, &info->version) || info->version < kMinPieVersion) {
    *error = "not a PIE file of version 2, 3 or 4";
    return false;
  }
  uint32_t first_vertex = 0, level_points = 0;
  for (size_t i = 1; i < lines.size(); ++i) {
    const Line& l = lines[i];
    if (!l.keyword()) continue;  // data of a section we skip
    const std::string& key = l.tokens[0];
    uint32_t count = 0;
    if (key == "LEVEL") {
      ++info->levels;
      first_vertex = static_cast<uint32_t>(out->vertex_count());
      level_points = 0;
    } else if (key == "POINTS") {
      if (l.tokens.size() < 2 || !parse_uint(l.tokens[1], kMaxPiePoints, &count)) {
        *error = at(l, "bad POINTS count");
        return false;
      }
      first_vertex = static_cast<uint32_t>(out->vertex_count());
      level_points = count;
      if (!read_points(lines, &i, count, out, error)) return false;
    } else if (key == "POLYGONS") {
      if (l.tokens.size() < 2 || !parse_uint(l.tokens[1], kMaxPiePolygons, &count)) {
        *error = at(l, "bad POLYGONS count");
        return false;
      }
      if (!read_polygons(lines, &i, count, first_vertex, level_points, out, info, error)) return false;
    }
  }
  if (out->triangle_count() == 0) {
    *error = "no polygons";
    return false;
  }
  std::string bad = out->validate();
  if (!bad.empty()) {
    *error = bad;
    return false;
  }
  return true;
}

bool read_pie(const std::string& path, Mesh* out, PieInfo* info, std::string* error) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxPieFileBytes) {
    *error = ec ? ec.message() : "file larger than " + std::to_string(kMaxPieFileBytes) + " bytes";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = "cannot open";
    return false;
  }
  if (!parse_pie(in, out, info, error)) return false;
  out->name = std::filesystem::path(path).stem().string();
  return true;
}

Eigen::Matrix4d pie_to_metres() {
  Eigen::Matrix4d t = Eigen::Matrix4d::Zero();
  t(0, 2) = kPieMetresPerUnit;  // forward <- PIE z
  t(1, 0) = kPieMetresPerUnit;  // left    <- PIE x
  t(2, 1) = kPieMetresPerUnit;  // up      <- PIE y
  t(3, 3) = 1.0;
  return t;
}

}  // namespace spinhash::host
