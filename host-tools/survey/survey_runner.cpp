#include "survey/survey_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "blob/file_io.hpp"
#include "config/config_text.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/json_line.hpp"
#include "pipeline/segment_cell.hpp"
#include "pipeline/spill_folder.hpp"
#include "pipeline/version.hpp"
#include "spinhash/internal/fnv1a.hpp"
#include "survey/footprint.hpp"
#include "survey/interrupt_cleanup.hpp"
#include "survey/survey_progress.hpp"
#include "survey/tile_run.hpp"

namespace spinhash::survey {
namespace {

namespace fs = std::filesystem;
using pipeline::json_string;

constexpr size_t kHashChunk = size_t{1} << 20;

// The database's digest (FNV-1a 64 of its bytes): a result made with
// another database is not reused.
std::string file_digest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> buf(kHashChunk);
  uint64_t h = kFnv1a64Basis;
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    h = fnv1a64_update(h, buf.data(), static_cast<size_t>(in.gcount()));
  }
  char hex[20];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

// A fresh run forgets the stored results: only the *.result files of the
// results folder go (never a folder the user may have named DIR/tiles).
void remove_results(const std::string& folder) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
    if (e.path().extension() == ".result") fs::remove(e.path(), ec);
}

// What the readers hand out of a tile (cloud/point_filter.hpp): a result
// stored by a binary or a run that read otherwise is run again, not kept.
std::string points_read(const host::PointFilter& filter) {
  return "without-withheld-and-classes-" + host::classes_text(filter);
}

std::string text_digest(const std::string& text) {
  char digest[20];
  std::snprintf(digest, sizeof digest, "%016llx",
                static_cast<unsigned long long>(fnv1a64(text.data(), text.size())));
  return digest;
}

// Every setting a tile's answers depend on: a stored result made with
// another scene setting (its terrain, gates, windows: every field of
// scene_fields.h, so a field a newer binary adds too) or recognizer field
// is run again.
std::string settings_key(const SurveyOptions& o) {
  return "spinhash=" + std::string(pipeline::version()) + ";db=" + file_digest(o.db_path) +
         ";scene=" + text_digest(host::config_text(o.scene)) +
         ";recognizer=" + text_digest(host::config_text(o.scene.recognizer)) +
         ";work_crs=" + escape_line(o.work.named ? o.work.crs.proj_definition() : "") +
         ";points=" + points_read(o.filter);
}

// A stored result is a few lines per object: far below this.
constexpr uint64_t kMaxResultBytes = uint64_t{1} << 30;

// The stored result of a task, when it exists and was made from the same inputs.
bool load_result(const std::string& out_dir, const SurveyTask& task, TileResult* r) {
  std::string text, error;
  return host::read_file(result_path(out_dir, task.tile.name), kMaxResultBytes, &text, &error) &&
         parse_result_text(text, r, &error) && r->key == task.key;
}

std::string manifest_json(const PreparedSurvey& s, const std::vector<bool>& done) {
  std::string tiles;
  for (size_t i = 0; i < s.tasks.size(); ++i)
    tiles +=
        (tiles.empty() ? "\n  " : ",\n  ") + std::string("{\"tile\":") + json_string(s.tasks[i].tile.name) +
        ",\"path\":" + json_string(s.tasks[i].tile.path) + ",\"done\":" + (done[i] ? "true" : "false") +
        ",\"result\":" + json_string(std::string(kResultsFolder) + "/" + s.tasks[i].tile.name + ".result") +
        "}";
  return "{\"database\":" + json_string(s.options.db_path) +
         ",\"buffer_m\":" + pipeline::json_number(s.options.buffer) +
         ",\"crs\":" + json_string(s.catalogue.crs.describe()) + ",\"tiles\":[" + tiles + "\n]}\n";
}

bool write_manifest(const PreparedSurvey& s, const std::vector<bool>& done, std::string* error) {
  const std::string text = manifest_json(s, done);
  return host::write_file_atomically(s.options.out_dir + "/manifest.json", text.data(), text.size(), error);
}

}  // namespace

SceneConfig default_survey_scene() {
  SceneConfig c;
  c.recognizer.ground.ground_clearance = 0.0f;  // the scene's terrain classifier removes the ground
  c.max_tile_points = 0;                        // sized per tile from its density (tile_stream.hpp)
  return c;
}

std::string result_path(const std::string& out_dir, const std::string& tile_name) {
  return out_dir + "/" + kResultsFolder + "/" + tile_name + ".result";
}

bool store_result(const std::string& out_dir, const TileResult& result, std::string* error) {
  const std::string text = result_text(result);
  return host::write_file_atomically(result_path(out_dir, result.name), text.data(), text.size(), error);
}

namespace {
// One segmentation cell for every tile (pipeline/segment_cell.hpp), from
// the points and bounding boxes of all the tiles' headers: neighbours then
// segment a vehicle they share alike, and each finds it once.
float survey_segment_cell(const Catalogue& catalogue, const SceneConfig& scene) {
  uint64_t points = 0;
  double area = 0.0;
  for (const CatalogueTile& t : catalogue.tiles) {
    if (!t.error.empty() || !t.header.count_known || !t.header.bounds_known) continue;
    points += t.header.point_count;
    area += (t.header.max[0] - t.header.min[0]) * (t.header.max[1] - t.header.min[1]);
  }
  return pipeline::segment_cell_for_density(scene.segment_cell, pipeline::tile_density(points, area),
                                            scene.window_core);
}
}  // namespace

bool prepare_survey(const SurveyOptions& options, const std::vector<std::string>& args, PreparedSurvey* out,
                    std::string* error) {
  PreparedSurvey s;
  s.options = options;
  std::vector<std::string> paths;
  if (!expand_tile_arguments(args, &paths, error)) return false;
  s.catalogue = read_catalogue(paths);
  if (!check_catalogue(s.catalogue, options.work, error)) return false;
  for (const CatalogueTile& t : s.catalogue.tiles)
    if (!t.error.empty()) s.refused.push_back(refusal(t.name, t.path, t.error));
  std::error_code ec;
  const std::string results = options.out_dir + "/" + kResultsFolder;
  fs::create_directories(results, ec);
  if (ec) {
    *error = "cannot make " + results + ": " + ec.message();
    return false;
  }
  if (!options.resume) remove_results(results);
  s.options.scene.segment_cell = survey_segment_cell(s.catalogue, options.scene);
  s.tasks = plan_survey(s.catalogue, options.buffer, settings_key(s.options));
  for (SurveyTask& t : s.tasks) {
    t.filter = options.filter;
    t.segment_cell = s.options.scene.segment_cell;
  }
  if (!s.tasks.empty() && !s.tasks[0].crs.empty()) {
    try {
      const ToWgs84 probe(s.tasks[0].crs);  // refused now rather than on every tile
    } catch (const std::exception& e) {
      *error = e.what();
      return false;
    }
  }
  for (const SurveyTask& t : s.tasks) {
    TileResult r;
    s.done.push_back(options.resume && load_result(options.out_dir, t, &r));
  }
  if (!write_manifest(s, s.done, error)) return false;
  *out = std::move(s);
  return true;
}

int finish_survey(const PreparedSurvey& s, const std::vector<Refusal>& failed, double wall_s,
                  std::string* error) {
  std::vector<TileResult> results;
  std::vector<bool> done(s.tasks.size(), false);
  bool all_ok = s.refused.empty() && failed.empty();
  for (size_t i = 0; i < s.tasks.size(); ++i) {
    TileResult r;
    if (!load_result(s.options.out_dir, s.tasks[i], &r)) {
      all_ok = false;
      continue;
    }
    all_ok = all_ok && r.status == "ok";
    done[i] = true;
    results.push_back(std::move(r));
  }
  SurveyReport report;
  report.database = s.options.db_path;
  report.buffer = s.options.buffer;
  report.jobs = s.options.jobs;
  report.dropped_classes = s.options.filter.classes();
  report.segment_cell = s.options.scene.segment_cell;
  report.tiles_total = static_cast<uint32_t>(s.catalogue.tiles.size());
  for (bool d : s.done) report.tiles_resumed += d ? 1u : 0u;
  report.wall_s = wall_s;
  report.refused = s.refused;
  report.refused.insert(report.refused.end(), failed.begin(), failed.end());
  if (!write_survey_outputs(s.options.out_dir, s.catalogue, results, report, error) ||
      !write_manifest(s, done, error))
    return pipeline::kExitError;
  return all_ok ? pipeline::kExitOk : pipeline::kExitCheckFailed;
}

int run_survey(const SurveyOptions& options, const std::vector<std::string>& args) {
  const auto t0 = std::chrono::steady_clock::now();
  const InterruptCleanup cleanup("survey");  // before any worker thread
  pipeline::report_stale_spill_folders("survey");
  PreparedSurvey s;
  std::string error;
  pipeline::DatabaseFile db;
  if (!pipeline::load_database(options.db_path, &db, &error) || !prepare_survey(options, args, &s, &error)) {
    std::fprintf(stderr, "spinhash survey: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::vector<size_t> todo;
  for (size_t i = 0; i < s.tasks.size(); ++i)
    if (!s.done[i]) todo.push_back(i);
  std::string kept;
  for (size_t i = 0; i < s.tasks.size(); ++i)
    if (s.done[i]) kept += (kept.empty() ? "" : ", ") + s.tasks[i].tile.name;
  if (!kept.empty())
    std::fprintf(stderr, "spinhash survey: kept %zu tile%s a previous run finished: %s\n",
                 s.tasks.size() - todo.size(), s.tasks.size() - todo.size() == 1 ? "" : "s", kept.c_str());
  SurveyProgress progress(static_cast<uint32_t>(s.catalogue.tiles.size()),
                          static_cast<uint32_t>(s.tasks.size() - todo.size()),
                          static_cast<uint32_t>(s.refused.size()), options.quiet);
  std::vector<Refusal> failed;
  std::mutex failed_mutex;
  std::atomic<size_t> next{0};
  const auto worker = [&]() {
    for (size_t k; (k = next++) < todo.size();) {
      const SurveyTask& task = s.tasks[todo[k]];
      std::string why;
      try {
        const TileResult r = run_task(db.db, task, options.scene, options.order_memory_points);
        if (store_result(options.out_dir, r, &why)) {
          progress.tile_done(r.points_tile);
          continue;
        }
      } catch (const std::exception& e) {
        why = e.what();
      }
      std::lock_guard<std::mutex> lock(failed_mutex);
      failed.push_back(refusal(task.tile.name, task.tile.path, why));
      std::fprintf(stderr, "spinhash survey: %s: %s\n", task.tile.path.c_str(), failed.back().reason.c_str());
      progress.tile_done(0);
    }
  };
  const unsigned jobs = options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (unsigned j = 0; j < std::min<size_t>(jobs, std::max<size_t>(todo.size(), 1)); ++j)
    threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  std::sort(failed.begin(), failed.end(), [](const Refusal& a, const Refusal& b) { return a.path < b.path; });
  s.options.jobs = jobs;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int code = finish_survey(s, failed, wall, &error);
  if (code == pipeline::kExitError) std::fprintf(stderr, "spinhash survey: %s\n", error.c_str());
  for (const Refusal& r : s.refused)
    std::fprintf(stderr, "spinhash survey: refused %s: %s\n", r.path.c_str(), r.reason.c_str());
  if (code != pipeline::kExitError)
    std::fprintf(stderr,
                 "spinhash survey: wrote "
                 "%s/{detections.jsonl,detections.geojson,detections.gpkg,overview.png,survey.json}\n",
                 options.out_dir.c_str());
  return code;
}

}  // namespace spinhash::survey
