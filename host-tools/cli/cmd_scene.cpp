// spinhash scene --db DB.shdb [--mode bran|sran|sind] [--top N] TILE...
// One JSON object per object of each tile per line on stdout (vehicle
// candidates with their ranking and pose; the other objects with model null);
// per-tile stage statistics, progress and errors on stderr.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cloud/metric_source.hpp"
#include "flags/recognizer_flags.hpp"
#include "flags/scene_flags.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/json_line.hpp"
#include "pipeline/object_box.hpp"
#include "pipeline/object_json.hpp"
#include "pipeline/object_units.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/scene_session.hpp"
#include "pipeline/spill_folder.hpp"
#include "pipeline/tile_stream.hpp"
#include "render/tile_picture.hpp"

namespace spinhash::cli {

using pipeline::DatabaseFile;
namespace {

constexpr uint32_t kPicturePoints = 2000000;  // an even sample of the tile for --picture-out

struct SceneArgs {
  std::string db_path;
  std::vector<std::string> tiles;
  std::string picture_dir;   // a top-down PNG per tile, when given
  host::WorkCrs work;        // --work-crs: the CRS to work in (else each file's own)
  host::PointFilter filter;  // --drop-class: classes left out besides noise
  SceneConfig config;
  size_t order_memory_points = pipeline::kOrderMemoryPoints;  // --order-memory
};

bool write_picture(const SceneArgs& a, const std::string& name, const std::vector<double>& xyz,
                   const std::vector<host::PictureBox>& boxes, uint32_t confident, std::string* error) {
  const std::string title =
      name + ": " + std::to_string(boxes.size()) + " objects, " + std::to_string(confident) + " confident";
  return host::write_tile_picture(a.picture_dir + "/" + name + ".png", xyz, boxes, title, error);
}

// The stream's counts of what it did not answer, for stderr ("" when none).
std::string lost_text(const StreamStats& st) {
  std::string s;
  auto add = [&s](uint64_t v, const char* what) {
    if (v > 0) s += (s.empty() ? "" : ", ") + std::to_string(v) + " " + what;
  };
  add(st.points_outside, "points outside the swath");
  add(st.points_late, "points late");
  add(st.points_glitch, "points of unconfirmed jumps");
  add(st.points_overflow, "points past the buffer");
  add(st.windows_overflowed, "windows over capacity (objects not answered)");
  return s;
}

// One tile through the stream, in metres of the CRS worked in (the file's
// own, or --work-crs): JSON lines as objects come, back in that CRS's
// units; stats on stderr. An unreadable tile gets its line too.
int run_tile(const SceneArgs& a, const DatabaseFile& file, const std::string& path) {
  const std::string name = host::cloud_name(path);
  pipeline::TileStreamOptions options;  // units: metres, as the door hands them
  options.scene = a.config;
  options.order_memory_points = a.order_memory_points;
  options.picture_points = a.picture_dir.empty() ? 0u : kPicturePoints;
  std::vector<host::PictureBox> boxes;
  uint32_t index = 0, confident = 0;
  std::string crs;  // the CRS worked in, on every line (empty: none declared)
  host::AxisUnits units;
  const auto start = std::chrono::steady_clock::now();
  const pipeline::ObjectCallback print = [&](const SceneObject& metres) {
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::vector<RankedModel> ranking;
    const SceneObject o = pipeline::in_file_units(metres, units, &ranking);
    std::printf("%s\n", pipeline::object_json(name, index++, file.db, o, crs, ms).c_str());
    if (!a.picture_dir.empty()) boxes.push_back(pipeline::object_box(file.db, metres));
    confident += o.confident ? 1u : 0u;
  };
  pipeline::TileStreamResult r;
  try {
    std::unique_ptr<host::MetricSource> source = host::open_metric_source(path, a.work, a.filter);
    const host::ToMetres& to_metres = source->to_metres();
    if (to_metres.work_crs().known()) crs = to_metres.work_crs().describe();
    units = to_metres.units();
    for (const std::string& note : to_metres.notes())
      std::fprintf(stderr, "spinhash scene: %s: %s\n", name.c_str(), note.c_str());
    r = pipeline::stream_tile(file.db, *source, options, print);
    const std::string noise = host::dropped_note(source->points_noise(), a.filter);
    if (!noise.empty()) std::fprintf(stderr, "spinhash scene: %s: %s\n", name.c_str(), noise.c_str());
  } catch (const std::exception& e) {
    std::fflush(stdout);  // the objects already reported stay; the tile's status line follows them
    std::printf("%s\n", pipeline::unreadable_json("tile", name, e.what()).c_str());
    std::fflush(stdout);
    std::fprintf(stderr, "spinhash scene: %s\n", e.what());  // the reader names the file
    return kExitCheckFailed;
  }
  std::fflush(stdout);
  const std::string lost = lost_text(r.stats);
  const std::string crs_text = crs.empty() ? "unknown (the file's own coordinates, taken as metres)"
                                           : crs + " (" + units.short_text() + ")";
  std::fprintf(
      stderr,
      "spinhash scene: %s: %s; CRS %s; %s; %.1f points per m2, segmentation cell %.2f m; %llu windows in %u "
      "bands, workspace %.1f MB; read %.1f ms, stream %.1f ms%s%s\n",
      name.c_str(), status_name(r.status), crs_text.c_str(),
      pipeline::scene_stats_text(r.stats.scene).c_str(), r.density, static_cast<double>(r.segment_cell),
      static_cast<unsigned long long>(r.stats.windows), r.bands, r.workspace_bytes / 1e6, r.read_ms,
      r.stream_ms, lost.empty() ? "" : "; not answered: ", lost.c_str());
  int exit_code = r.status == Status::kOk ? kExitOk : kExitCheckFailed;
  std::string error;
  if (!a.picture_dir.empty() && !write_picture(a, name, r.picture_xyz, boxes, confident, &error)) {
    std::fprintf(stderr, "spinhash scene: %s\n", error.c_str());
    exit_code = kExitError;
  }
  return exit_code;
}

int run_scene(const SceneArgs& a) {
  pipeline::report_stale_spill_folders("scene");
  DatabaseFile file;
  std::string error;
  if (!pipeline::load_database(a.db_path, &file, &error)) {
    std::fprintf(stderr, "spinhash scene: %s\n", error.c_str());
    return kExitError;
  }
  int exit_code = kExitOk;
  pipeline::Progress progress("scene", static_cast<uint32_t>(a.tiles.size()));
  for (size_t t = 0; t < a.tiles.size(); ++t) {
    const int code = run_tile(a, file, a.tiles[t]);
    if (code != kExitOk && exit_code != kExitError) exit_code = code;
    progress.tick(static_cast<uint32_t>(t + 1));
  }
  return exit_code;
}

}  // namespace

void add_scene_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<SceneArgs>();
  a->config.recognizer.ground.ground_clearance = 0.0f;  // the scene's terrain classifier removes the ground
  a->config.max_tile_points = 0;                        // sized per tile from its density (tile_stream.hpp)
  CLI::App* cmd = app.add_subcommand(
      "scene",
      "find and recognise every vehicle in airborne lidar tiles (LAS, LAZ, COPC, PLY or x y z text, z up)");
  cmd->add_option("--db", a->db_path, "database file")->required()->check(CLI::ExistingFile);
  flags::add_scene_flags(cmd, &a->config);  // --top, --window-core, --max-window-points, ...
  cmd->add_option("--picture-out", a->picture_dir,
                  "folder for a top-down PNG per tile: objects outlined and labelled (green: confident)")
      ->check(CLI::ExistingDirectory);
  add_work_crs_option(cmd, &a->work);
  add_drop_class_option(cmd, &a->filter);
  add_order_memory_option(cmd, &a->order_memory_points);
  cmd->add_option("tiles", a->tiles, "point cloud files ('-': stdin)")->required();
  flags::add_recognizer_flags(cmd, &a->config.recognizer);
  cmd->callback([a, exit_code]() {
    refuse_repeated_stdin(a->tiles);
    *exit_code = run_scene(*a);
  });
}

}  // namespace spinhash::cli
