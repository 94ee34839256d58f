#include "survey/tile_result.hpp"

#include <cstdio>
#include <sstream>

#include "survey/task.hpp"

namespace spinhash::survey {
namespace {

constexpr const char* kMagic = "spinhash-tile-result 1";

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

template <class Rest>
host::PictureBox parse_box(std::istringstream& ls, const Rest& rest) {
  host::PictureBox b;
  int style = 0;
  ls >> style >> b.center[0] >> b.center[1] >> b.length >> b.width >> b.heading_deg;
  b.style = static_cast<host::BoxStyle>(style);
  b.label = unescape_line(rest(ls));
  return b;
}

}  // namespace

std::string result_text(const TileResult& r) {
  std::string s = std::string(kMagic) + "\n";
  s += "index " + std::to_string(r.index) + "\n";
  s += "name " + escape_line(r.name) + "\npath " + escape_line(r.path) + "\nkey " + escape_line(r.key) + "\n";
  s += "status " + r.status + "\n";
  s += "points " + std::to_string(r.points_tile) + " " + std::to_string(r.points_buffer) + " " +
       std::to_string(r.points_noise) + "\n";
  s += "objects " + std::to_string(r.objects_not_owned) + " " + std::to_string(r.objects_in_holes) + "\n";
  s += "times " + num(r.read_ms) + " " + num(r.stream_ms) + " " + num(r.total_ms) + "\n";
  for (const auto& kv : r.kinds)
    s += "kind " + std::to_string(kv.second) + " " + escape_line(kv.first) + "\n";
  for (const auto& kv : r.models)
    s += "model " + std::to_string(kv.second.candidates) + " " + std::to_string(kv.second.confident) + " " +
         escape_line(kv.first) + "\n";
  for (const Column& c : r.columns)
    s += "column " + std::string(1, static_cast<char>(c.type)) + " " + c.name + "\n";
  for (const std::string& l : r.lines) s += "line " + l + "\n";  // JSON: no raw newline
  for (const std::string& f : r.features) s += "feature " + f + "\n";
  for (const host::PictureBox& b : r.boxes)
    s += "box " + std::to_string(static_cast<int>(b.style)) + " " + num(b.center[0]) + " " +
         num(b.center[1]) + " " + num(b.length) + " " + num(b.width) + " " + num(b.heading_deg) + " " +
         escape_line(b.label) + "\n";
  return s + "end\n";
}

bool parse_result_text(const std::string& text, TileResult* out, std::string* error) {
  std::istringstream in(text);
  std::string line;
  TileResult r;
  bool header = false, end = false;
  const auto rest = [](std::istringstream& ls) {
    std::string v;
    std::getline(ls, v);
    return v.empty() ? v : v.substr(1);
  };
  while (std::getline(in, line)) {
    if (line == kMagic) {
      header = true;
      continue;
    }
    std::istringstream ls(line);
    std::string w;
    ls >> w;
    if (w == "index")
      ls >> r.index;
    else if (w == "name")
      r.name = unescape_line(rest(ls));
    else if (w == "path")
      r.path = unescape_line(rest(ls));
    else if (w == "key")
      r.key = unescape_line(rest(ls));
    else if (w == "status")
      ls >> r.status;
    else if (w == "points")
      ls >> r.points_tile >> r.points_buffer >> r.points_noise;
    else if (w == "objects")
      ls >> r.objects_not_owned >> r.objects_in_holes;
    else if (w == "times")
      ls >> r.read_ms >> r.stream_ms >> r.total_ms;
    else if (w == "kind") {
      uint32_t n = 0;
      ls >> n;
      r.kinds[unescape_line(rest(ls))] = n;
    } else if (w == "model") {
      ModelCount m;
      ls >> m.candidates >> m.confident;
      r.models[unescape_line(rest(ls))] = m;
    } else if (w == "column") {
      char type = 's';
      ls >> type;
      r.columns.push_back({rest(ls), static_cast<ColumnType>(type)});
    } else if (w == "line")
      r.lines.push_back(rest(ls));
    else if (w == "feature")
      r.features.push_back(rest(ls));
    else if (w == "box")
      r.boxes.push_back(parse_box(ls, rest));
    else if (w == "end")
      end = true;
  }
  if (!header || !end) {
    *error = "not a tile result (or cut short)";
    return false;
  }
  *out = std::move(r);
  return true;
}

}  // namespace spinhash::survey
