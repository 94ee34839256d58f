#include "survey/task.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "cloud/crs_resolve.hpp"
#include "cloud/crs_units.hpp"

namespace spinhash::survey {
namespace {

namespace fs = std::filesystem;

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string rect_text(const Rect& r) {
  return num(r.min[0]) + " " + num(r.min[1]) + " " + num(r.max[0]) + " " + num(r.max[1]);
}

// The file's identity for resume: path, size and modification time.
std::string file_identity(const std::string& path) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  const auto time = fs::last_write_time(path, ec).time_since_epoch().count();
  return escape_line(path) + ":" + std::to_string(ec ? 0 : size) + ":" + std::to_string(ec ? 0 : time);
}

Rect core_of(const CatalogueTile& t) {
  Rect r;
  r.min[0] = t.header.min[0], r.min[1] = t.header.min[1];
  r.max[0] = t.header.max[0], r.max[1] = t.header.max[1];
  return r;
}

std::string task_key(const SurveyTask& t, double buffer, const std::string& settings) {
  std::string k = settings + ";buffer=" + num(buffer) + ";tile=" + file_identity(t.tile.path) + "@" +
                  rect_text(t.tile.core);
  for (const TaskTile& n : t.neighbours) k += ";neighbour=" + file_identity(n.path) + "@" + rect_text(n.core);
  return k;
}

}  // namespace

Rect Rect::grown(double d) const {
  Rect r = *this;
  r.min[0] -= d, r.min[1] -= d, r.max[0] += d, r.max[1] += d;
  return r;
}

bool Rect::intersects(const Rect& o) const {
  return min[0] <= o.max[0] && o.min[0] <= max[0] && min[1] <= o.max[1] && o.min[1] <= max[1];
}

std::vector<SurveyTask> plan_survey(const Catalogue& catalogue, double buffer, const std::string& settings) {
  std::vector<SurveyTask> tasks;
  const host::AxisUnits units = host::axis_units(catalogue.crs);
  const double grow = std::max(buffer, 2.0 * kGapTolerance);  // m, as the bounds
  for (size_t i = 0; i < catalogue.tiles.size(); ++i) {
    const CatalogueTile& t = catalogue.tiles[i];
    if (!t.error.empty()) continue;
    SurveyTask task;
    task.index = static_cast<uint32_t>(i);
    task.tile = {t.path, t.name, core_of(t)};
    task.seen = task.tile.core.grown(grow);
    for (size_t j = 0; j < catalogue.tiles.size(); ++j) {
      const CatalogueTile& n = catalogue.tiles[j];
      if (j != i && n.error.empty() && core_of(n).intersects(task.seen))
        task.neighbours.push_back({n.path, n.name, core_of(n)});
    }
    task.crs = catalogue.crs.proj_definition();
    task.crs_named = catalogue.crs_named;
    task.crs_name = catalogue.crs.describe();
    task.units = units;
    task.key = task_key(task, buffer, settings);
    tasks.push_back(std::move(task));
  }
  return tasks;
}

host::WorkCrs SurveyTask::work() const {
  host::WorkCrs w;
  w.named = crs_named;
  if (!crs.empty()) {
    std::string error;
    if (!host::crs_from_user(crs, &w.crs, &error)) throw std::runtime_error("survey task: " + error);
    w.crs.source.clear();  // the survey's CRS, not one the user typed (unless named)
  }
  w.crs.units = units;  // as the catalogue resolved them (GeoKeys' unit codes are not in the definition)
  return w;
}

std::string escape_line(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '\\')
      o += "\\\\";
    else if (c == '\n')
      o += "\\n";
    else if (c == '\t')
      o += "\\t";
    else
      o += c;
  }
  return o;
}

std::string unescape_line(const std::string& s) {
  std::string o;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '\\' || i + 1 == s.size()) {
      o += s[i];
      continue;
    }
    const char c = s[++i];
    o += c == 'n' ? '\n' : c == 't' ? '\t' : c;
  }
  return o;
}

std::string task_text(const SurveyTask& t) {
  std::string s = "spinhash-survey-task 1\nindex " + std::to_string(t.index) + "\n";
  s += "tile " + rect_text(t.tile.core) + " " + escape_line(t.tile.path) + "\n";
  for (const TaskTile& n : t.neighbours)
    s += "neighbour " + rect_text(n.core) + " " + escape_line(n.path) + "\n";
  s += "seen " + rect_text(t.seen) + "\n";
  s += "crs " + escape_line(t.crs) + "\ncrs_named " + (t.crs_named ? "1" : "0") + "\ncrs_name " +
       escape_line(t.crs_name) + "\n";
  s += "units " + num(t.units.horizontal) + " " + num(t.units.vertical) + " " +
       (t.units.geographic ? "1" : "0") + "\n";
  s += "drop_classes " + host::classes_text(t.filter) + "\n";
  s += "segment_cell " + num(t.segment_cell) + "\n";
  return s + "key " + escape_line(t.key) + "\nend\n";
}

bool parse_task_text(const std::string& text, SurveyTask* task, std::string* error) {
  std::istringstream in(text);
  std::string line;
  SurveyTask t;
  bool header = false, end = false;
  const auto rest = [](std::istringstream& ls) {
    std::string r;
    std::getline(ls, r);
    return unescape_line(r.empty() ? r : r.substr(1));
  };
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "spinhash-survey-task")
      header = true;
    else if (word == "index")
      ls >> t.index;
    else if (word == "tile" || word == "neighbour") {
      TaskTile tt;
      ls >> tt.core.min[0] >> tt.core.min[1] >> tt.core.max[0] >> tt.core.max[1];
      tt.path = rest(ls);
      tt.name = host::cloud_name(tt.path);
      (word == "tile" ? t.tile : t.neighbours.emplace_back()) = tt;
    } else if (word == "seen")
      ls >> t.seen.min[0] >> t.seen.min[1] >> t.seen.max[0] >> t.seen.max[1];
    else if (word == "crs")
      t.crs = rest(ls);
    else if (word == "crs_named")
      ls >> t.crs_named;
    else if (word == "crs_name")
      t.crs_name = rest(ls);
    else if (word == "units")
      ls >> t.units.horizontal >> t.units.vertical >> t.units.geographic;
    else if (word == "drop_classes") {
      std::string classes, class_error;
      ls >> classes;
      if (!host::add_drop_classes(classes, &t.filter, &class_error)) {
        *error = "survey task: drop_classes: " + class_error;
        return false;
      }
    } else if (word == "segment_cell")
      ls >> t.segment_cell;
    else if (word == "key")
      t.key = rest(ls);
    else if (word == "end")
      end = true;
    if (ls.fail()) break;
  }
  if (!header || !end || t.tile.path.empty()) {
    *error = "not a survey task (or cut short)";
    return false;
  }
  *task = std::move(t);
  return true;
}

}  // namespace spinhash::survey
