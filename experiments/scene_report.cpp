// scene: CSVs (per condition, per vehicle, per false alarm, per tile), plots
// against each swept variable, and summary.md with the scene's targets.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "csv_table.hpp"
#include "gnuplot.hpp"
#include "output_dir.hpp"
#include "plot_styles.hpp"
#include "scene_data.hpp"
#include "stats.hpp"

namespace spinhash::experiment {
namespace {

// The scene's targets, on tiles with slopes up to kTargetMaxSlope at the
// reference spacing and noise.
constexpr double kTargetRecall = 0.95;
constexpr double kTargetTop1 = 0.90;
constexpr double kTargetAlarmsPerTile = 0.5;
constexpr double kTargetMaxSlope = 12.0;
constexpr int kPlotWidth = 640, kPlotHeight = 420;
constexpr double kXPadding = 0.05;   // of the swept range, each side
constexpr double kMinXPad = 0.01;    // a single value
constexpr double kY2Headroom = 1.1;  // false alarms axis above its largest value

struct Totals {
  uint32_t tiles = 0, vehicles = 0, found = 0, top1 = 0, confident_right = 0, confident_wrong = 0, alarms = 0;
  double mean_ms = 0, median_ms = 0, mean_points = 0;
  double rate(uint32_t k) const { return vehicles ? double(k) / vehicles : 0.0; }
  double alarms_per_tile() const { return tiles ? double(alarms) / tiles : 0.0; }
};

Totals totals(const SceneRun& run, const std::function<bool(const SceneCondition&)>& keep) {
  Totals t;
  std::vector<double> ms, pts;
  for (const SceneTileRecord& r : run.tile_records) {
    if (!keep(run.conditions[r.condition])) continue;
    ++t.tiles;
    t.vehicles += r.vehicles, t.found += r.found, t.top1 += r.top1;
    t.confident_right += r.confident_right, t.confident_wrong += r.confident_wrong,
        t.alarms += r.false_alarms;
    ms.push_back(r.ms);
    pts.push_back(r.points);
  }
  t.mean_ms = mean_of(ms), t.median_ms = median_of(ms), t.mean_points = mean_of(pts);
  return t;
}

std::string pct(double p) { return num(100.0 * p, 3); }

struct Sweep {
  const char* name;     // "slope", "spacing", "noise"
  const char* x_title;  // axis title
  const std::vector<double>* values;
  double SceneCondition::*field;
};

std::vector<Sweep> sweeps(const SceneRun& run) {
  return {{"slope", "terrain slope (degrees)", &run.slopes, &SceneCondition::slope_deg},
          {"spacing", "point spacing on the ground (m)", &run.spacings, &SceneCondition::spacing},
          {"noise", "range noise sigma (m)", &run.noises, &SceneCondition::noise}};
}

// The condition of a sweep at `value`: the reference with that field changed.
SceneCondition at(const SceneRun& run, const Sweep& s, double value) {
  SceneCondition c = run.reference;
  c.*(s.field) = value;
  return c;
}

bool same(const SceneCondition& a, const SceneCondition& b) {
  return a.slope_deg == b.slope_deg && a.spacing == b.spacing && a.noise == b.noise;
}

bool write_tables(const SceneRun& run, std::string* error) {
  CsvTable scene({"sweep", "slope_deg", "spacing", "noise", "tiles", "vehicles", "found", "recall", "top1",
                  "top1_rate", "confident_right", "confident_right_rate", "confident_wrong", "false_alarms",
                  "false_alarms_per_tile", "mean_ms", "median_ms", "mean_points"});
  for (const Sweep& s : sweeps(run)) {
    CsvTable plot({"x", "recall_pct", "top1_pct", "confident_right_pct", "false_alarms_per_tile"});
    for (double v : *s.values) {
      const SceneCondition c = at(run, s, v);
      const Totals t = totals(run, [&](const SceneCondition& d) { return same(c, d); });
      scene.add({s.name, num(c.slope_deg), num(c.spacing), num(c.noise), std::to_string(t.tiles),
                 std::to_string(t.vehicles), std::to_string(t.found), num(t.rate(t.found), 4),
                 std::to_string(t.top1), num(t.rate(t.top1), 4), std::to_string(t.confident_right),
                 num(t.rate(t.confident_right), 4), std::to_string(t.confident_wrong),
                 std::to_string(t.alarms), num(t.alarms_per_tile(), 4), num(t.mean_ms, 4),
                 num(t.median_ms, 4), num(t.mean_points, 6)});
      plot.add({num(v), pct(t.rate(t.found)), pct(t.rate(t.top1)), pct(t.rate(t.confident_right)),
                num(t.alarms_per_tile(), 4)});
    }
    if (!plot.write(run.out_dir + "/plot_" + s.name + ".csv", error)) return false;
  }
  CsvTable objects({"slope_deg", "spacing", "noise", "tile", "kind", "model", "side_by_side", "under_tree",
                    "points", "found", "distance_m", "answer", "confident", "score", "score_second",
                    "features", "ground_gap", "nearest_m", "nearest_answer"});
  for (const SceneVehicleRecord& v : run.vehicles)
    objects.add({num(run.conditions[v.condition].slope_deg), num(run.conditions[v.condition].spacing),
                 num(run.conditions[v.condition].noise), std::to_string(v.tile),
                 host::scene_object_kind_name(v.kind), v.model, (v.flags & host::kSideBySide) ? "1" : "0",
                 (v.flags & host::kUnderTree) ? "1" : "0", std::to_string(v.points), v.found ? "1" : "0",
                 num(v.distance, 3), v.answer, v.confident ? "1" : "0", num(v.score, 5),
                 num(v.score_second, 5), std::to_string(v.features), num(v.ground_gap, 4),
                 v.nearest_m < 0 ? "" : num(v.nearest_m, 3), v.nearest_answer});
  CsvTable alarms(
      {"slope_deg", "spacing", "noise", "tile", "on", "answer", "score", "length", "width", "height"});
  for (const SceneFalseAlarm& a : run.alarms)
    alarms.add({num(run.conditions[a.condition].slope_deg), num(run.conditions[a.condition].spacing),
                num(run.conditions[a.condition].noise), std::to_string(a.tile), a.on, a.answer,
                num(a.score, 5), num(a.extent[0], 3), num(a.extent[1], 3), num(a.extent[2], 3)});
  CsvTable tiles({"slope_deg", "spacing", "noise", "tile", "points", "objects", "vehicles", "found", "top1",
                  "confident_right", "confident_wrong", "false_alarms", "ms"});
  for (const SceneTileRecord& t : run.tile_records)
    tiles.add({num(run.conditions[t.condition].slope_deg), num(run.conditions[t.condition].spacing),
               num(run.conditions[t.condition].noise), std::to_string(t.tile), std::to_string(t.points),
               std::to_string(t.objects), std::to_string(t.vehicles), std::to_string(t.found),
               std::to_string(t.top1), std::to_string(t.confident_right), std::to_string(t.confident_wrong),
               std::to_string(t.false_alarms), num(t.ms, 4)});
  return scene.write(run.out_dir + "/scene.csv", error) &&
         objects.write(run.out_dir + "/per_object.csv", error) &&
         alarms.write(run.out_dir + "/false_alarms.csv", error) &&
         tiles.write(run.out_dir + "/per_tile.csv", error);
}

// Recall, top-1 and confident-right (%, left axis) and false alarms per tile (right axis).
bool write_plots(const SceneRun& run, std::vector<std::string>* made, std::string* error) {
  if (!plot_format().available()) return true;  // no gnuplot: the CSVs stand alone
  for (const Sweep& s : sweeps(run)) {
    const auto [lo, hi] = std::minmax_element(s.values->begin(), s.values->end());
    double most_alarms = 0.0;
    for (double v : *s.values) {
      const SceneCondition c = at(run, s, v);
      most_alarms = std::max(
          most_alarms, totals(run, [&](const SceneCondition& d) { return same(c, d); }).alarms_per_tile());
    }
    const double pad = *hi > *lo ? kXPadding * (*hi - *lo) : std::max(kXPadding * std::abs(*lo), kMinXPad);
    std::ostringstream p;
    p << plot_style_lines() << "set xrange [" << *lo - pad << ":" << *hi + pad << "]\n"
      << "set datafile separator ','\nset key bottom left\nset grid\n"
      << "set title 'scene: " << run.tiles << " tiles per point, " << s.name
      << " swept (others at the reference)'\n"
      << "set xlabel '" << s.x_title << "'\nset ylabel '% of database vehicles'\nset yrange [0:105]\n"
      << "set y2label 'false alarms per tile'\nset y2range [0:" << std::max(1.0, kY2Headroom * most_alarms)
      << "]\nset y2tics\nset ytics nomirror\n"
      << "plot 'plot_" << s.name << ".csv' using 1:2 with linespoints ls 1 title 'found',"
      << " '' using 1:3 with linespoints ls 2 title 'ranked right first',"
      << " '' using 1:4 with linespoints ls 3 title 'confident and right',"
      << " '' using 1:5 axes x1y2 with linespoints ls 4 title 'false alarms per tile'\n";
    const std::string name = std::string("scene_") + s.name;
    if (!render_plot(run.out_dir, name, p.str(), kPlotWidth, kPlotHeight, error)) return false;
    made->push_back(plot_file(name));
  }
  return true;
}

std::string yes_no(bool ok) { return ok ? "**met**" : "**not met**"; }

void targets_section(const SceneRun& run, std::ostringstream& md) {
  const auto in_target = [&](const SceneCondition& c) {
    return c.slope_deg <= kTargetMaxSlope && c.spacing == run.reference.spacing &&
           c.noise == run.reference.noise;
  };
  const Totals t = totals(run, in_target);
  md << "## Targets\n\nTiles with slopes up to " << kTargetMaxSlope << " degrees at spacing "
     << run.reference.spacing << " m and noise " << run.reference.noise << " m: " << t.tiles << " tiles, "
     << t.vehicles << " database vehicles.\n\n| measure | target | measured | |\n|---|---|---|---|\n"
     << "| found | >= " << pct(kTargetRecall) << "% | " << pct(t.rate(t.found)) << "% (" << t.found << ") | "
     << yes_no(t.rate(t.found) >= kTargetRecall) << " |\n"
     << "| ranked right first (of all vehicles) | >= " << pct(kTargetTop1) << "% | " << pct(t.rate(t.top1))
     << "% (" << t.top1 << ") | " << yes_no(t.rate(t.top1) >= kTargetTop1) << " |\n"
     << "| false alarms per tile | <= " << kTargetAlarmsPerTile << " | " << num(t.alarms_per_tile(), 3)
     << " (" << t.alarms << ") | " << yes_no(t.alarms_per_tile() <= kTargetAlarmsPerTile) << " |\n"
     << "| confident and right | | " << pct(t.rate(t.confident_right)) << "% | |\n"
     << "| confident and wrong (database vehicles) | | " << t.confident_wrong << " | |\n\n";
  uint32_t missed = 0, off_centre = 0;
  for (const SceneVehicleRecord& v : run.vehicles) {
    if (v.kind != host::SceneObjectKind::kVehicle || v.found || !in_target(run.conditions[v.condition]))
      continue;
    ++missed;
    off_centre += v.nearest_m >= 0.0 && v.nearest_answer == v.model ? 1u : 0u;
  }
  md << "Not found: " << missed << "; of them " << off_centre << " with a vehicle-sized object "
     << kMatchDistance << "-" << kNearestReach
     << " m from the footprint centre whose first model is the vehicle's (found off-centre: e.g. a tracked "
        "vehicle's hull without its gun barrel, which the truth footprint includes; per_object.csv, "
        "nearest_m).\n\n";
  // By situation, over the same tiles.
  md << "By situation (same tiles):\n\n| vehicles | count | found | ranked right first | confident and right "
        "|\n"
     << "|---|---|---|---|---|\n";
  const char* names[] = {"side by side", "under a tree", "neither"};
  for (int k = 0; k < 3; ++k) {
    uint32_t n = 0, found = 0, top1 = 0, conf = 0;
    for (const SceneVehicleRecord& v : run.vehicles) {
      if (v.kind != host::SceneObjectKind::kVehicle || !in_target(run.conditions[v.condition])) continue;
      const bool pick = k == 0   ? (v.flags & host::kSideBySide) != 0
                        : k == 1 ? (v.flags & host::kUnderTree) != 0
                                 : (v.flags & (host::kSideBySide | host::kUnderTree)) == 0;
      if (!pick) continue;
      ++n, found += v.found, top1 += v.found && v.answer == v.model,
          conf += v.found && v.answer == v.model && v.confident;
    }
    const double d = n ? n : 1;
    md << "| " << names[k] << " | " << n << " | " << pct(found / d) << "% | " << pct(top1 / d) << "% | "
       << pct(conf / d) << "% |\n";
  }
  md << "\n";
}

void sweep_tables(const SceneRun& run, std::ostringstream& md) {
  for (const Sweep& s : sweeps(run)) {
    md << "## " << s.name << " swept\n\n| " << s.x_title
       << " | tiles | vehicles | found | ranked right first | confident and right | confident wrong | false "
          "alarms "
          "per tile | mean ms | median ms | mean points |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (double v : *s.values) {
      const SceneCondition c = at(run, s, v);
      const Totals t = totals(run, [&](const SceneCondition& d) { return same(c, d); });
      md << "| " << num(v) << " | " << t.tiles << " | " << t.vehicles << " | " << pct(t.rate(t.found))
         << "% | " << pct(t.rate(t.top1)) << "% | " << pct(t.rate(t.confident_right)) << "% | "
         << t.confident_wrong << " | " << num(t.alarms_per_tile(), 3) << " | " << num(t.mean_ms, 4) << " | "
         << num(t.median_ms, 4) << " | " << num(t.mean_points, 6) << " |\n";
    }
    md << "\n";
  }
}

void alarms_section(const SceneRun& run, std::ostringstream& md) {
  md << "## What the false alarms were on (all conditions)\n\n";
  if (run.alarms.empty()) {
    md << "None.\n\n";
    return;
  }
  std::vector<std::pair<std::string, uint32_t>> by;
  for (const SceneFalseAlarm& a : run.alarms) {
    auto it = std::find_if(by.begin(), by.end(), [&](const auto& p) { return p.first == a.on; });
    if (it == by.end())
      by.push_back({a.on, 1u});
    else
      ++it->second;
  }
  md << "| on | count |\n|---|---|\n";
  for (const auto& p : by) md << "| " << p.first << " | " << p.second << " |\n";
  md << "\n";
}

}  // namespace

bool write_scene_report(const SceneRun& run, std::string* error) {
  std::vector<std::string> plots;
  if (!write_tables(run, error) || !write_plots(run, &plots, error)) return false;
  std::ostringstream md;
  md << "# Scene: simulated airborne tiles\n\n";
  if (!run.command.empty()) md << "Command: `" << run.command << "` (" << num(run.seconds, 3) << " s)\n\n";
  md << "- Models: " << run.source << "\n- Database: " << run.database << "\n- Recognizer: " << run.recognizer
     << "\n- Tiles: " << run.tile_text << "\n- Reference: " << run.reference.label() << "; " << run.tiles
     << " tiles per condition\n- Found: a vehicle-sized object (recognised or not) whose centre is within "
     << kMatchDistance
     << " m of the vehicle's footprint centre; ranked right first: its first model is the vehicle's; false "
        "alarm: a confident answer on anything but a database vehicle (a non-vehicle, an unknown vehicle, a "
        "second object on one vehicle, nothing).\n\n";
  targets_section(run, md);
  sweep_tables(run, md);
  alarms_section(run, md);
  md << "## Files\n\nscene.csv (per condition), per_object.csv (per vehicle), false_alarms.csv, per_tile.csv";
  for (const std::string& p : plots) md << ", " << p;
  md << "\n";
  return write_text(run.out_dir + "/summary.md", md.str(), error);
}

}  // namespace spinhash::experiment
