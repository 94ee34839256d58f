// spinhash scene --db DB.shdb [--mode bran|sran|sind] [--top N] TILE...
// One JSON object per object of each tile per line on stdout (vehicle
// candidates with their ranking and pose; the other objects with model null);
// per-tile stage statistics, progress and errors on stderr.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cli/json_line.hpp"
#include "cli/result_json.hpp"
#include "cloud/cloud_reader.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/recognizer_flags.hpp"
#include "pipeline/scene_session.hpp"
#include "render/tile_picture.hpp"

namespace spinhash::cli {

using pipeline::DatabaseFile;
using pipeline::SceneSession;
namespace {

struct SceneArgs {
  std::string db_path;
  std::vector<std::string> tiles;
  std::string picture_dir;  // a top-down PNG per tile, when given
  SceneConfig config;
};

// The tile's objects as outlined boxes: the model (with "?" when not
// confident) on vehicle candidates, what it is on the others.
std::vector<host::PictureBox> picture_boxes(const Database& db, const SceneResult& r) {
  std::vector<host::PictureBox> boxes;
  for (uint32_t k = 0; k < r.object_count; ++k) {
    const SceneObject& o = r.objects[k];
    host::PictureBox b;
    b.center[0] = o.center[0], b.center[1] = o.center[1];
    b.length = o.extent[0], b.width = o.extent[1], b.heading_deg = o.heading_deg;
    if (o.kind == ObjectKind::kVehicleCandidate && o.ranking_count > 0) {
      b.label = pipeline::model_name(db, o.ranking[0].model) + (o.confident ? "" : " ?");
      b.style = o.confident ? host::BoxStyle::kConfident : host::BoxStyle::kUnsure;
    } else {
      b.label = object_kind_name(o.kind);
      b.style = o.kind == ObjectKind::kVehicleCandidate || o.kind == ObjectKind::kUnknown
                    ? host::BoxStyle::kUnsure
                    : host::BoxStyle::kNotVehicle;
    }
    boxes.push_back(b);
  }
  return boxes;
}

bool write_picture(const SceneArgs& a, const std::string& name, const std::vector<double>& xyz,
                   const Database& db, const SceneResult& r, std::string* error) {
  uint32_t confident = 0;
  for (uint32_t k = 0; k < r.object_count; ++k) confident += r.objects[k].confident ? 1u : 0u;
  const std::string title =
      name + ": " + std::to_string(r.object_count) + " objects, " + std::to_string(confident) + " confident";
  return host::write_tile_picture(a.picture_dir + "/" + name + ".png", xyz, picture_boxes(db, r), title,
                                  error);
}

std::string triple_json(const double v[3], int digits) {
  return "[" + json_number(v[0], digits) + "," + json_number(v[1], digits) + "," + json_number(v[2], digits) +
         "]";
}

std::string object_json(const std::string& tile, uint32_t k, const Database& db, const SceneObject& o,
                        double time_ms) {
  const bool ranked = o.ranking_count > 0;
  std::string s =
      "{\"tile\":" + json_string(tile) + ",\"object\":" + std::to_string(k) +
      ",\"kind\":" + json_string(object_kind_name(o.kind)) + ",\"status\":\"" + status_word(o.status) +
      "\",\"model\":" + (ranked ? json_string(pipeline::model_name(db, o.ranking[0].model)) : "null") +
      ",\"confident\":" + (o.confident ? "true" : "false") +
      ",\"group_size\":" + std::to_string(o.group_size) +
      ",\"score\":" + (ranked ? json_number(o.ranking[0].score) : "null") + ",\"ranking\":[";
  for (uint32_t j = 0; j < o.ranking_count; ++j)
    s += std::string(j ? "," : "") +
         "{\"model\":" + json_string(pipeline::model_name(db, o.ranking[j].model)) +
         ",\"score\":" + json_number(o.ranking[j].score) + "}";
  s += "],\"pose\":" + (ranked && o.ranking[0].has_pose ? pose_json(o.ranking[0].pose) : std::string("null"));
  s +=
      ",\"ground_gap\":" + (std::isfinite(o.ground_gap) ? json_number(o.ground_gap, 4) : std::string("null"));
  const double extent[3] = {o.extent[0], o.extent[1], o.extent[2]};
  s += ",\"points\":" + std::to_string(o.points) + ",\"center\":" + triple_json(o.center, 15) +
       ",\"extent\":" + triple_json(extent, 4) + ",\"time_ms\":" + json_number(time_ms, 6) + "," +
       json_version_member() + "}";
  return s;
}

int run_scene(const SceneArgs& a) {
  DatabaseFile file;
  SceneSession session;
  std::string error;
  if (!pipeline::load_database(a.db_path, &file, &error) || !session.init(&file.db, a.config, &error)) {
    std::fprintf(stderr, "spinhash scene: %s\n", error.c_str());
    return kExitError;
  }
  int exit_code = kExitOk;
  pipeline::Progress progress("scene", static_cast<uint32_t>(a.tiles.size()));
  for (size_t t = 0; t < a.tiles.size(); ++t) {
    const std::string& path = a.tiles[t];
    const std::string name = host::cloud_name(path);
    std::vector<double> xyz;
    if (!host::read_cloud(path, &xyz, &error)) {
      std::fprintf(stderr, "spinhash scene: %s\n", error.c_str());  // the reader names the file
      exit_code = kExitCheckFailed;
      continue;
    }
    const SceneResult r = session.recognize(xyz);
    // The tile's wall time on every line: objects share the terrain and segmentation work.
    for (uint32_t k = 0; k < r.object_count; ++k)
      std::printf("%s\n", object_json(name, k, file.db, r.objects[k], session.last_ms()).c_str());
    std::fflush(stdout);
    std::fprintf(stderr, "spinhash scene: %s: %s; %s; %.1f ms\n", name.c_str(), status_name(r.status),
                 pipeline::scene_stats_text(r.stats).c_str(), session.last_ms());
    if (r.status != Status::kOk) exit_code = kExitCheckFailed;
    if (!a.picture_dir.empty() && !write_picture(a, name, xyz, file.db, r, &error)) {
      std::fprintf(stderr, "spinhash scene: %s\n", error.c_str());
      exit_code = kExitError;
    }
    progress.tick(static_cast<uint32_t>(t + 1));
  }
  return exit_code;
}

}  // namespace

void add_scene_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<SceneArgs>();
  a->config.recognizer.ground_clearance = 0.0f;  // the scene's terrain classifier removes the ground
  CLI::App* cmd = app.add_subcommand(
      "scene", "find and recognise every vehicle in airborne lidar tiles (LAS, PLY or x y z text, z up)");
  cmd->add_option("--db", a->db_path, "database file")->required();
  cmd->add_option("--top", a->config.top_n, "models listed per object")->check(CLI::Range(1u, 64u));
  cmd->add_option("--max-tile-points", a->config.max_tile_points, "largest tile (more: refused)")
      ->check(CLI::Range(1u, 1u << 26));
  cmd->add_option("--max-objects", a->config.max_objects,
                  "objects per tile (more: the rest are not recognised)")
      ->check(CLI::Range(1u, 1u << 16));
  cmd->add_option("--picture-out", a->picture_dir,
                  "folder for a top-down PNG per tile: objects outlined and labelled (green: confident)")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("tiles", a->tiles, "point cloud files ('-': stdin)")->required();
  pipeline::add_recognizer_flags(cmd, &a->config.recognizer);
  cmd->callback([a, exit_code]() {
    refuse_repeated_stdin(a->tiles);
    *exit_code = run_scene(*a);
  });
}

}  // namespace spinhash::cli
