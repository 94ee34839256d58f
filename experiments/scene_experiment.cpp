// spinhash-experiment scene: simulated airborne tiles (host-tools/scan/
// scene_simulator) through the SceneRecognizer, scored against their truth,
// sweeping slope, point spacing and noise one at a time around a reference.
#include <chrono>
#include <cstdio>
#include <memory>

#include "bran_knobs.hpp"
#include "cloud/cloud_writer.hpp"
#include "config_text.hpp"
#include "experiments.hpp"
#include "memory_database.hpp"
#include "mesh/vehicle_generator.hpp"
#include "model_set.hpp"
#include "modes.hpp"
#include "output_dir.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/scene_session.hpp"
#include "scene_data.hpp"

namespace spinhash::experiment {
namespace {

using pipeline::SceneSession;

constexpr uint32_t kMaxTiles = 1000;                  // per condition
constexpr uint32_t kDefaultModels = 56;               // the paper's database
constexpr uint32_t kUnknownFleetMembers = 7;          // procedural vehicles past the database: one per family
constexpr uint32_t kExperimentTilePoints = 1u << 20;  // 40 m at 0.05 m spacing is ~700 000 points

struct SceneArgs {
  std::string out;
  uint32_t tiles = 4;
  uint32_t models = kDefaultModels;
  std::vector<std::string> meshes, unknown;
  uint32_t unknown_vehicles = 1;
  std::vector<double> slopes{0, 4, 8, 12, 15}, spacings{0.05, 0.10, 0.15}, noises{0.02, 0.05, 0.10};
  SceneCondition reference;
  double size = 40.0;
  uint32_t vehicles = 5;
  uint64_t seed = 1, fleet_seed = 1;
  std::vector<std::string> settings;  // --set FIELD=VALUE
  std::string mode = "bran";
  bool models_given = false;
  bool save_tiles = false;  // OUT/tiles/: each tile's LAS and truth, for `spinhash scene --picture-out`
};

// The reference, then each sweep's other values (the reference is run once).
std::vector<SceneCondition> make_conditions(const SceneArgs& a) {
  std::vector<SceneCondition> out{a.reference};
  auto add = [&](SceneCondition c) {
    for (const SceneCondition& d : out)
      if (d.slope_deg == c.slope_deg && d.spacing == c.spacing && d.noise == c.noise) return;
    out.push_back(c);
  };
  for (double s : a.slopes) add({s, a.reference.spacing, a.reference.noise});
  for (double s : a.spacings) add({a.reference.slope_deg, s, a.reference.noise});
  for (double n : a.noises) add({a.reference.slope_deg, a.reference.spacing, n});
  return out;
}

struct Fleet {
  std::vector<host::Mesh> known, unknown;
};

bool load_fleet(const SceneArgs& a, std::vector<pipeline::ModelMesh>* models, Fleet* fleet,
                std::string* source, std::string* error) {
  std::vector<pipeline::ModelMesh> unknown;
  if (a.meshes.empty()) {
    *models = generated_models(a.models + kUnknownFleetMembers, a.fleet_seed);
    unknown.assign(models->begin() + a.models, models->end());
    models->resize(a.models);
    *source = "procedural fleet of " + std::to_string(a.models) + " (seed " + std::to_string(a.fleet_seed) +
              "); unknown vehicles: its next " + std::to_string(kUnknownFleetMembers) + " members";
  } else {
    if (!loaded_models(a.meshes, a.models_given ? a.models : 0u, models, error)) return false;
    *source = std::to_string(models->size()) + " meshes from";
    for (const std::string& m : a.meshes) *source += " " + m;
    if (!a.unknown.empty()) {
      if (!loaded_models(a.unknown, 0u, &unknown, error)) return false;
      *source += "; unknown vehicles from";
      for (const std::string& m : a.unknown) *source += " " + m;
    }
  }
  for (const pipeline::ModelMesh& m : *models)
    fleet->known.push_back(m.mesh), fleet->known.back().name = m.name;
  for (const pipeline::ModelMesh& m : unknown)
    fleet->unknown.push_back(m.mesh), fleet->unknown.back().name = m.name;
  return true;
}

host::SceneOptions tile_options(const SceneArgs& a, const SceneCondition& c, uint32_t unknown,
                                uint32_t tile) {
  host::SceneOptions o;
  o.size = a.size;
  o.vehicles = a.vehicles;
  o.unknown_vehicles = unknown;
  o.slope_deg = c.slope_deg;
  o.point_spacing = c.spacing;
  o.noise_sigma = c.noise;
  o.seed = a.seed + tile;  // the same layouts in every condition: paired comparisons
  return o;
}

bool save_tile(const SceneArgs& a, uint32_t condition, uint32_t tile, const host::SceneScan& scan,
               std::string* error) {
  const std::string stem = a.out + "/tiles/c" + std::to_string(condition) + "-t" + std::to_string(tile);
  return make_output_dir(a.out + "/tiles", error) &&
         host::write_cloud(stem + ".las", scan.xyz, scan.classification, false, error) &&
         host::write_scene_truth(stem + ".truth.csv", scan.objects, error);
}

// Every tile of every condition: simulate, recognise, score.
bool run_tiles(const SceneArgs& a, const Fleet& fleet, uint32_t unknown, const Database& db,
               SceneSession& session, SceneRun* run, std::string* error) {
  for (uint32_t c = 0; c < run->conditions.size(); ++c) {
    const SceneCondition& cond = run->conditions[c];
    std::fprintf(stderr, "spinhash-experiment scene: condition %u/%zu: %s\n", c + 1, run->conditions.size(),
                 cond.label().c_str());
    pipeline::Progress progress(cond.label(), a.tiles);
    for (uint32_t t = 0; t < a.tiles; ++t) {
      const host::SceneScan scan =
          host::simulate_scene(fleet.known, fleet.unknown, tile_options(a, cond, unknown, t));
      if (!scan.ok()) {
        *error = "tile " + std::to_string(t) + " of " + cond.label() + ": " + scan.error;
        return false;
      }
      if (a.save_tiles && !save_tile(a, c, t, scan, error)) return false;
      const SceneResult r = session.recognize(scan.xyz);
      if (r.status != Status::kOk && r.status != Status::kTooManyObjects)
        std::fprintf(stderr, "spinhash-experiment scene: tile %u of %s: %s\n", t, cond.label().c_str(),
                     status_name(r.status));
      score_tile(scan, r, db, c, t, session.last_ms(), run);
      progress.tick(t + 1);
    }
  }
  return true;
}

int run_scene(const SceneArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  SceneRun run;
  run.out_dir = a.out;
  run.command = invoked_command_line();
  run.tiles = a.tiles;
  run.reference = a.reference;
  run.slopes = a.slopes, run.spacings = a.spacings, run.noises = a.noises;
  run.conditions = make_conditions(a);
  std::vector<Mode> modes;
  std::vector<pipeline::ModelMesh> models;
  std::vector<host::ModelCloud> clouds;
  Fleet fleet;
  std::unique_ptr<MemoryDatabase> mdb;
  SceneSession session;
  SceneConfig cfg;
  auto fail = [&](const std::string& e) {
    std::fprintf(stderr, "spinhash-experiment scene: %s\n", e.c_str());
    return pipeline::kExitError;
  };
  if (!parse_modes({a.mode}, &modes, &error) || modes.size() != 1 || !make_output_dir(a.out, &error) ||
      !load_fleet(a, &models, &fleet, &run.source, &error))
    return fail(error.empty() ? "--mode: one of bran, sran, sind" : error);
  const uint32_t unknown = fleet.unknown.empty() ? 0u : a.unknown_vehicles;
  cfg.recognizer.mode = modes[0];
  cfg.recognizer.ground.ground_clearance =
      0.0f;  // as `spinhash scene`: the terrain classifier removes the ground
  cfg.max_tile_points = kExperimentTilePoints;
  apply_settings(a.settings, &cfg.recognizer);
  if (!model_clouds(models, &clouds, &error) ||
      !(mdb = build_memory_database(clouds, host::BuildOptions{}, false, &error)) ||
      !session.init(&mdb->db, cfg, &error))
    return fail(error);
  clouds.clear();
  run.database = database_text(*mdb);
  run.recognizer = recognizer_text(cfg.recognizer);
  run.tile_text =
      std::to_string(static_cast<int>(a.size)) + " x " + std::to_string(static_cast<int>(a.size)) +
      " m tiles, " + std::to_string(a.vehicles) +
      " database vehicles (two side by side, one under a "
      "tree), " +
      std::to_string(unknown) +
      " unknown vehicle(s), 3 trees, a building, a wall, 3 crates; 4 oblique views (elevation 45-60"
      " degrees, range 100-200 m); tile seeds " +
      std::to_string(a.seed) + ".." + std::to_string(a.seed + a.tiles - 1) +
      " in every condition; scene workspace " + std::to_string(session.workspace_bytes() >> 20) +
      " MiB (max_tile_points " + std::to_string(cfg.max_tile_points) + ")";
  std::fprintf(stderr, "spinhash-experiment scene: %s\n", run.database.c_str());
  if (!run_tiles(a, fleet, unknown, mdb->db, session, &run, &error)) return fail(error);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!write_scene_report(run, &error)) return fail(error);
  std::fprintf(stderr, "spinhash-experiment scene: wrote %s/summary.md (%.0f s)\n", a.out.c_str(),
               run.seconds);
  return pipeline::kExitOk;
}

}  // namespace

void add_scene_experiment(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<SceneArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "scene",
      "simulated tiles through the scene recognizer: recall, top-1, false alarms vs slope, spacing, noise");
  a->out = default_output_dir("scene");
  cmd->add_option("--out", a->out,
                  "output folder (CSV, plots, summary.md); default out/scene (git ignores out/)");
  cmd->add_option("--tiles", a->tiles, "tiles per condition")
      ->check(CLI::Range(1u, kMaxTiles))
      ->capture_default_str();
  cmd->add_option("--models", a->models, "procedural vehicles (with --meshes: use at most this many)")
      ->check(CLI::Range(2u, host::kMaxFleetSize))
      ->each([a](const std::string&) { a->models_given = true; })
      ->capture_default_str();
  cmd->add_option("--meshes", a->meshes, "model meshes (files or folders) instead of the procedural fleet");
  cmd->add_option("--unknown", a->unknown, "with --meshes: meshes of vehicles not in the database");
  cmd->add_option("--unknown-vehicles", a->unknown_vehicles, "unknown vehicles per tile")
      ->check(CLI::Range(0u, host::kMaxSceneVehicles))
      ->capture_default_str();
  cmd->add_option("--vehicles", a->vehicles, "database vehicles per tile")
      ->check(CLI::Range(1u, host::kMaxSceneVehicles))
      ->capture_default_str();
  cmd->add_option("--size", a->size, "tile side, m")
      ->check(CLI::Range(20.0, host::kMaxSceneSize))
      ->capture_default_str();
  cmd->add_option("--slopes", a->slopes, "terrain slopes swept, degrees")
      ->delimiter(',')
      ->check(CLI::Range(0.0, host::kMaxSceneSlopeDeg))
      ->capture_default_str();
  cmd->add_option("--spacings", a->spacings, "ground point spacings swept, m")
      ->delimiter(',')
      ->check(CLI::Range(0.02, 1.0))
      ->capture_default_str();
  cmd->add_option("--noises", a->noises, "range noise levels swept, m")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--ref-slope", a->reference.slope_deg, "the sweeps' centre: slope")
      ->check(CLI::Range(0.0, host::kMaxSceneSlopeDeg))
      ->capture_default_str();
  cmd->add_option("--ref-spacing", a->reference.spacing, "the sweeps' centre: spacing")
      ->check(CLI::Range(0.02, 1.0))
      ->capture_default_str();
  cmd->add_option("--ref-noise", a->reference.noise, "the sweeps' centre: noise")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--mode", a->mode, "bran, sran or sind")->capture_default_str();
  cmd->add_option("--seed", a->seed, "first tile's seed")->capture_default_str();
  cmd->add_option("--fleet-seed", a->fleet_seed, "seed of the procedural fleet")->capture_default_str();
  add_set_option(cmd, &a->settings);
  cmd->add_flag("--save-tiles", a->save_tiles,
                "write each tile (LAS) and its truth (CSV) to OUT/tiles/cCONDITION-tTILE.*");
  cmd->callback([a, exit_code]() { *exit_code = run_scene(*a); });
}

}  // namespace spinhash::experiment
