// spinhash-experiment stream: simulated flight lines (host-tools/scan/
// flight_line) pushed in scan order through the SceneStream, scored against
// their truth (scene_score.cpp): recall, top-1, confident false alarms,
// duplicates and points per second, against point spacing and vehicle
// density; and whether the answers depend on the chunking.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "config_text.hpp"
#include "csv_table.hpp"
#include "experiments.hpp"
#include "gnuplot.hpp"
#include "memory_database.hpp"
#include "model_set.hpp"
#include "output_dir.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/recognition_session.hpp"
#include "scan/flight_line.hpp"
#include "scene_data.hpp"
#include "spinhash/scene_stream.hpp"

namespace spinhash::experiment {
namespace {

constexpr uint32_t kDefaultModels = 56;
constexpr uint32_t kUnknownFleetMembers = 7;  // procedural members past the database: one per family
constexpr double kLineSpeed = 60.0;           // m/s
constexpr double kLagSlack = 20.0;            // m beyond the line's measured lag
constexpr uint32_t kPushChunk = 4096 / 24;    // points: a 4 kB chunk of doubles
constexpr double kAlarmArea = 1600.0;         // m^2: false alarms are counted per this area

struct StreamArgs {
  std::string out;
  double length = 1000.0, size = 100.0;
  std::vector<double> spacings{0.07, 0.10, 0.25};
  std::vector<uint32_t> vehicles{22};  // per segment
  double slope = 8.0, noise = 0.05;
  uint32_t unknown_vehicles = 1;
  uint32_t parked_rows = 3, row_length = 4;
  uint64_t seed = 1, fleet_seed = 1;
  double chunking_length = 300.0;  // m: the line run whole, in 4 kB chunks and point by point
};

// Each reported object copied, rankings included (the sink's are transient).
struct Collected {
  std::vector<SceneObject> objects;
  std::vector<std::vector<RankedModel>> rankings;
  static void sink(void* context, const SceneObject& o, int64_t, uint32_t) {
    auto* c = static_cast<Collected*>(context);
    c->objects.push_back(o);
    c->rankings.emplace_back(o.ranking, o.ranking + o.ranking_count);
  }
  SceneResult result() {
    for (size_t k = 0; k < objects.size(); ++k) objects[k].ranking = rankings[k].data();
    SceneResult r;
    r.status = Status::kOk;
    r.objects = objects.data();
    r.object_count = static_cast<uint32_t>(objects.size());
    return r;
  }
};

// The stream for a line of `width` m (its segments' side) along +y, its
// origin the first point pushed: the swath covers the width either side.
StreamConfig line_config(double width, const host::FlightLineScan& line) {
  StreamConfig c;
  c.scene.recognizer.ground.ground_clearance = 0.0f;
  c.heading_deg = 90.0f;  // the line runs along +y
  c.swath_min = c.own_min = static_cast<float>(-width);
  c.swath_max = c.own_max = static_cast<float>(width);
  c.max_lag = static_cast<float>(line.max_lag + kLagSlack);
  c.scene.max_tile_points = 1u << 22;
  c.max_buffered_points = 1u << 24;
  return c;
}

struct Pushed {
  Collected collected;
  StreamStats stats;
  Status status = Status::kOk;
  double ms = 0.0;
};

// The line pushed in chunks of `chunk` points (its origin: the first point).
Pushed push_line(const Database& db, const host::FlightLineScan& line, const StreamConfig& config,
                 size_t chunk) {
  Pushed p;
  const size_t bytes = required_stream_workspace_bytes(config);
  host::AlignedBytes ws(bytes);
  SceneStream stream;
  p.status = stream.init(&db, config, ws.data(), bytes, Collected::sink, &p.collected);
  if (p.status != Status::kOk) return p;
  const auto t0 = std::chrono::steady_clock::now();
  const size_t n = line.scan.size();
  for (size_t i = 0; i < n; i += chunk) {
    const Status s = stream.push(line.scan.xyz.data() + 3 * i, static_cast<uint32_t>(std::min(chunk, n - i)));
    if (s != Status::kOk) p.status = s;
  }
  const Status f = stream.flush();
  if (f != Status::kOk) p.status = f;
  p.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  p.stats = stream.stats();
  return p;
}

host::FlightLineOptions line_options(const StreamArgs& a, double spacing, uint32_t vehicles, double length,
                                     uint32_t unknown) {
  host::FlightLineOptions o;
  o.length = length;
  o.speed = kLineSpeed;
  o.segment.size = a.size;
  o.segment.vehicles = vehicles;
  o.segment.unknown_vehicles = unknown;
  o.segment.parked_rows = a.parked_rows;
  o.segment.row_length = a.row_length;
  o.segment.trees = 6;
  o.segment.buildings = 2;
  o.segment.walls = 2;
  o.segment.crates = 4;
  o.segment.slope_deg = a.slope;
  o.segment.point_spacing = spacing;
  o.segment.noise_sigma = a.noise;
  o.segment.seed = a.seed;
  return o;
}

// Vehicles with more than one vehicle-sized detection on them; each such
// detection described on stderr (points, extent, centre), to tell a split
// object from one reported twice.
uint32_t duplicates(const host::SceneScan& scan, const SceneResult& r) {
  uint32_t dup = 0;
  for (const host::SceneTruth& v : scan.objects) {
    if (v.kind != host::SceneObjectKind::kVehicle && v.kind != host::SceneObjectKind::kUnknownVehicle)
      continue;
    uint32_t on = 0;
    for (uint32_t k = 0; k < r.object_count; ++k) {
      const SceneObject& o = r.objects[k];
      if (o.kind != ObjectKind::kVehicleCandidate && o.kind != ObjectKind::kUnknown) continue;
      on += std::hypot(o.center[0] - v.center.x(), o.center[1] - v.center.y()) <= kMatchDistance ? 1u : 0u;
    }
    if (on < 2) continue;
    ++dup;
    for (uint32_t k = 0; k < r.object_count; ++k) {
      const SceneObject& o = r.objects[k];
      if ((o.kind == ObjectKind::kVehicleCandidate || o.kind == ObjectKind::kUnknown) &&
          std::hypot(o.center[0] - v.center.x(), o.center[1] - v.center.y()) <= kMatchDistance)
        std::fprintf(
            stderr,
            "spinhash-experiment stream: %s twice: object of %u points, %.2f x %.2f m at (%.3f, %.3f)\n",
            v.model.c_str(), o.points, o.extent[0], o.extent[1], o.center[0], o.center[1]);
    }
  }
  return dup;
}

// The objects as text: what must not change with the chunking.
std::string fingerprint(const Database& db, const Collected& c) {
  std::string s;
  char buf[160];
  for (size_t k = 0; k < c.objects.size(); ++k) {
    const SceneObject& o = c.objects[k];
    std::snprintf(buf, sizeof buf, "%d %u %.9f %.9f %s %.6f %d\n", static_cast<int>(o.kind), o.points,
                  o.center[0], o.center[1],
                  o.ranking_count ? pipeline::model_name(db, c.rankings[k][0].model).c_str() : "-",
                  o.ranking_count ? static_cast<double>(c.rankings[k][0].score) : 0.0, o.confident ? 1 : 0);
    s += buf;
  }
  return s;
}

int run_stream(const StreamArgs& a) {
  auto fail = [](const std::string& e) {
    std::fprintf(stderr, "spinhash-experiment stream: %s\n", e.c_str());
    return pipeline::kExitError;
  };
  std::string error;
  if (!make_output_dir(a.out, &error)) return fail(error);
  std::vector<pipeline::ModelMesh> models =
      generated_models(kDefaultModels + kUnknownFleetMembers, a.fleet_seed);
  std::vector<host::Mesh> known, unknown;
  for (size_t i = 0; i < models.size(); ++i) {
    (i < kDefaultModels ? known : unknown).push_back(models[i].mesh);
    (i < kDefaultModels ? known : unknown).back().name = models[i].name;
  }
  models.resize(kDefaultModels);
  std::vector<host::ModelCloud> clouds;
  std::unique_ptr<MemoryDatabase> mdb;
  if (!model_clouds(models, &clouds, &error) ||
      !(mdb = build_memory_database(clouds, host::BuildOptions{}, false, &error)))
    return fail(error);
  CsvTable table({"spacing_m", "points_per_m2", "vehicles_per_segment", "points", "vehicles", "found", "top1",
                  "confident_right", "confident_false_alarms", "alarms_per_1600m2", "duplicates", "lag_m",
                  "seconds", "points_per_s", "windows", "late", "overflow"});
  std::string summary =
      "# stream experiment\n\n`" + invoked_command_line() + "`\n\n" + database_text(*mdb) +
      "\n\n| spacing | pts/m2 | veh/segment | points | vehicles | found | top-1 | "
      "confident false alarms /1600 m2 | duplicates | lag m | pts/s |\n|---|---|---|---|---|"
      "---|---|---|---|---|---|\n";
  for (double spacing : a.spacings)
    for (uint32_t vehicles : a.vehicles) {
      const host::FlightLineScan line = host::simulate_flight_line(
          known, unknown, line_options(a, spacing, vehicles, a.length, a.unknown_vehicles));
      if (!line.scan.ok()) return fail(line.scan.error);
      const StreamConfig cfg = line_config(a.size, line);
      Pushed p = push_line(mdb->db, line, cfg, kPushChunk);
      SceneRun run;
      const SceneResult r = p.collected.result();
      score_tile(line.scan, r, mdb->db, 0, 0, p.ms, &run);
      const SceneTileRecord& t = run.tile_records[0];
      const double area = a.length * a.size;
      const double alarms = t.false_alarms * kAlarmArea / area;
      const uint32_t dup = duplicates(line.scan, r);
      const double pps = line.scan.size() / (p.ms / 1000.0);
      table.add({num(spacing), num(1.0 / (spacing * spacing), 4), std::to_string(vehicles),
                 std::to_string(line.scan.size()), std::to_string(t.vehicles), std::to_string(t.found),
                 std::to_string(t.top1), std::to_string(t.confident_right), std::to_string(t.false_alarms),
                 num(alarms, 4), std::to_string(dup), num(line.max_lag, 4), num(p.ms / 1000.0, 4),
                 num(pps, 4), std::to_string(p.stats.windows), std::to_string(p.stats.points_late),
                 std::to_string(p.stats.points_overflow)});
      char row[400];
      std::snprintf(row, sizeof row,
                    "| %g | %.0f | %u | %zu | %u | %.1f %% | %.1f %% | %.3f | %u | %.0f | %.0f |\n", spacing,
                    1.0 / (spacing * spacing), vehicles, line.scan.size(), t.vehicles,
                    100.0 * t.found / std::max(1u, t.vehicles), 100.0 * t.top1 / std::max(1u, t.vehicles),
                    alarms, dup, line.max_lag, pps);
      summary += row;
      std::fprintf(stderr, "spinhash-experiment stream: %s", row);
    }
  // Chunking: the same line whole, in 4 kB chunks and one point at a time.
  const host::FlightLineScan short_line = host::simulate_flight_line(
      known, unknown,
      line_options(a, a.spacings.front(), a.vehicles.front(), a.chunking_length, a.unknown_vehicles));
  if (!short_line.scan.ok()) return fail(short_line.scan.error);
  const StreamConfig cfg = line_config(a.size, short_line);
  const std::string whole =
      fingerprint(mdb->db, push_line(mdb->db, short_line, cfg, short_line.scan.size()).collected);
  const std::string chunked = fingerprint(mdb->db, push_line(mdb->db, short_line, cfg, kPushChunk).collected);
  const std::string single = fingerprint(mdb->db, push_line(mdb->db, short_line, cfg, 1).collected);
  char verdict[300];
  std::snprintf(
      verdict, sizeof verdict,
      "\nChunking (a %.0f m line, %zu points, %zu objects): whole = 4 kB chunks: %s; whole = one point at "
      "a time: %s.\n",
      a.chunking_length, short_line.scan.size(), std::count(whole.begin(), whole.end(), '\n'),
      whole == chunked ? "identical" : "DIFFERENT", whole == single ? "identical" : "DIFFERENT");
  summary += verdict;
  std::fprintf(stderr, "spinhash-experiment stream:%s", verdict);
  if (!table.write(a.out + "/stream.csv", &error) || !write_text(a.out + "/summary.md", summary, &error))
    return fail(error);
  return whole == chunked && whole == single ? pipeline::kExitOk : pipeline::kExitCheckFailed;
}

}  // namespace

void add_stream_experiment(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<StreamArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "stream",
      "simulated flight lines through the SceneStream: recall, top-1, false alarms, duplicates, "
      "points/s vs density");
  a->out = default_output_dir("stream");
  cmd->add_option("--out", a->out, "output folder (CSV, summary.md); default out/stream (git ignores out/)");
  cmd->add_option("--length", a->length, "line length, m")
      ->check(CLI::Range(100.0, 20000.0))
      ->capture_default_str();
  cmd->add_option("--size", a->size, "segment (tile) side, m: the swath's width")
      ->check(CLI::Range(40.0, host::kMaxSceneSize))
      ->capture_default_str();
  cmd->add_option("--spacings", a->spacings, "ground point spacings, m")
      ->delimiter(',')
      ->check(CLI::Range(0.02, 1.0))
      ->capture_default_str();
  cmd->add_option("--vehicles", a->vehicles, "database vehicles per segment")
      ->delimiter(',')
      ->check(CLI::Range(1u, host::kMaxSceneVehicles))
      ->capture_default_str();
  cmd->add_option("--parked-rows", a->parked_rows, "rows of parked vehicles per segment")
      ->capture_default_str();
  cmd->add_option("--slope", a->slope, "terrain slope, degrees")->capture_default_str();
  cmd->add_option("--noise", a->noise, "range noise, m")->capture_default_str();
  cmd->add_option("--unknown-vehicles", a->unknown_vehicles, "unknown vehicles per segment")
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "line seed")->capture_default_str();
  cmd->add_option("--chunking-length", a->chunking_length,
                  "m of line fed whole, in 4 kB chunks and point by point")
      ->capture_default_str();
  cmd->callback([a, exit_code]() { *exit_code = run_stream(*a); });
}

}  // namespace spinhash::experiment
