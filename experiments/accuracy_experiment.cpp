// spinhash-experiment accuracy: Figure 9 (P(correct model in the top k)
// against k) for BRAN, SRAN and SIND under noise, occlusion and ground.
#include <cstdio>
#include <memory>

#include "accuracy_data.hpp"
#include "bran_knobs.hpp"
#include "config/mode_name.hpp"
#include "config_text.hpp"
#include "experiments.hpp"
#include "lookalikes.hpp"
#include "memory_database.hpp"
#include "mesh/vehicle_generator.hpp"
#include "model_set.hpp"
#include "modes.hpp"
#include "output_dir.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/progress.hpp"
#include "scan/scan_simulator.hpp"
#include "spinhash/limits.hpp"

namespace spinhash::experiment {
namespace {

constexpr uint32_t kMaxQueriesPerModel = 100;
constexpr uint32_t kMaxModelsDefault = 56;  // the paper's database

struct AccuracyArgs {
  std::string out;
  uint32_t models = kMaxModelsDefault;
  std::vector<std::string> meshes;
  uint32_t queries_per_model = 2;
  std::vector<double> noise{0.05, 0.10};
  std::vector<double> occlusion{0.0, 0.2, 0.4};
  std::vector<double> spacing{kPaperQuerySpacing};
  std::vector<double> slopes{0.0};  // degrees of terrain slope, for the conditions with ground
  uint32_t lookalikes = 0;          // copies of each model added to the database
  bool ground = false;
  bool ground_kept = false;
  double ground_margin = 3.0;  // m of ground beyond the vehicle on each side
  std::vector<std::string> modes{"bran", "sran", "sind"};
  uint64_t seed = 1;        // query scans
  uint64_t fleet_seed = 1;  // procedural vehicles
  uint32_t max_k = 10;
  BranKnobs bran;
  float ground_clearance = GroundParams{}.ground_clearance;
  bool models_given = false;
};

using Sessions = std::vector<std::unique_ptr<pipeline::RecognitionSession>>;

// One session per mode; keep_ground turns the recognizer's ground removal off.
bool open_sessions(const Database& db, const AccuracyArgs& a, const std::vector<Mode>& modes,
                   bool keep_ground, Sessions* out, std::string* error) {
  for (Mode m : modes) {
    RecognizerConfig cfg;  // library defaults (but the BRAN knobs): the experiment measures them
    cfg.mode = m;
    a.bran.apply(&cfg);
    cfg.ground.ground_clearance = keep_ground ? 0.0f : a.ground_clearance;
    out->push_back(std::make_unique<pipeline::RecognitionSession>());
    if (!out->back()->init(&db, cfg, error)) return false;
  }
  return true;
}

// Every query of every condition through every mode.
// Queries come from the first run->query_models meshes (the originals, when
// look-alike copies follow them).
bool run_queries(const AccuracyArgs& a, const std::vector<pipeline::ModelMesh>& meshes,
                 Sessions (&all_sessions)[2], AccuracyRun* run, std::string* error) {
  const uint32_t per_condition = run->query_models * a.queries_per_model;
  for (uint32_t c = 0; c < run->conditions.size(); ++c) {
    const QueryCondition& cond = run->conditions[c];
    std::fprintf(stderr, "spinhash-experiment accuracy: condition %u/%zu: %s\n", c + 1,
                 run->conditions.size(), cond.label().c_str());
    Sessions& sessions = all_sessions[cond.ground == Ground::kKept ? 1 : 0];
    pipeline::Progress progress(cond.label(), per_condition);
    uint32_t done = 0;
    for (uint32_t m = 0; m < run->query_models; ++m)
      for (uint32_t q = 0; q < a.queries_per_model; ++q) {
        Query query;
        if (!simulate_query(meshes[m].mesh, m, q, cond, a.seed, a.ground_margin, &query, error)) return false;
        for (uint32_t k = 0; k < sessions.size(); ++k)
          run->records.push_back(AccuracyRecord{c, k, m, q, static_cast<uint32_t>(query.xyz.size() / 3),
                                                query.object_points, recognise(*sessions[k], query)});
        progress.tick(++done);
      }
  }
  return true;
}

int run_accuracy(const AccuracyArgs& a) {
  std::string error;
  AccuracyRun run;
  run.out_dir = a.out;
  run.command = invoked_command_line();
  run.queries_per_model = a.queries_per_model;
  run.max_k = a.max_k;
  run.ground_margin = a.ground_margin;
  run.conditions = make_conditions(a.noise, a.occlusion, a.spacing, a.slopes, a.ground, a.ground_kept);
  std::vector<pipeline::ModelMesh> meshes;
  std::vector<host::ModelCloud> clouds;
  if (!parse_modes(a.modes, &run.modes, &error) || !make_output_dir(a.out, &error)) {
    std::fprintf(stderr, "spinhash-experiment accuracy: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  if (a.meshes.empty()) {
    meshes = generated_models(a.models, a.fleet_seed);
    run.source =
        "procedural fleet of " + std::to_string(a.models) + " (seed " + std::to_string(a.fleet_seed) + ")";
  } else if (!loaded_models(a.meshes, a.models_given ? a.models : 0u, &meshes, &error)) {
    std::fprintf(stderr, "spinhash-experiment accuracy: %s\n", error.c_str());
    return pipeline::kExitError;
  } else {
    run.source = std::to_string(meshes.size()) + " meshes from";
    for (const std::string& m : a.meshes) run.source += " " + m;
  }
  run.query_models = static_cast<uint32_t>(meshes.size());
  if (a.lookalikes > 0) {
    meshes = with_lookalikes(meshes, a.lookalikes);
    run.source +=
        ", each with " + std::to_string(a.lookalikes) +
        " look-alike copies (stretched, shortened, widened, narrowed, mirrored; queries from the originals)";
  }
  for (const pipeline::ModelMesh& m : meshes) {
    run.model_names.push_back(m.name);
    run.model_classes.push_back(static_cast<uint32_t>(m.vehicle_class));
  }
  std::unique_ptr<MemoryDatabase> mdb;
  Sessions sessions[2];  // [0] library defaults, [1] ground removal off (--ground-kept)
  if (!model_clouds(meshes, &clouds, &error) ||
      !(mdb = build_memory_database(clouds, host::BuildOptions{}, false, &error)) ||
      !open_sessions(mdb->db, a, run.modes, false, &sessions[0], &error) ||
      (a.ground_kept && !open_sessions(mdb->db, a, run.modes, true, &sessions[1], &error))) {
    std::fprintf(stderr, "spinhash-experiment accuracy: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  clouds.clear();
  run.database = database_text(*mdb);
  run.recognizer = recognizer_text(sessions[0].front()->config());
  std::fprintf(stderr, "spinhash-experiment accuracy: %s\n", run.database.c_str());
  if (!run_queries(a, meshes, sessions, &run, &error) || !write_accuracy_report(run, &error)) {
    std::fprintf(stderr, "spinhash-experiment accuracy: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::fprintf(stderr, "spinhash-experiment accuracy: wrote %s/summary.md\n", a.out.c_str());
  return pipeline::kExitOk;
}

}  // namespace

void add_accuracy_experiment(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<AccuracyArgs>();
  CLI::App* cmd = parent->add_subcommand("accuracy", "Figure 9: P(correct model in the top k) against k");
  a->out = default_output_dir("accuracy");
  cmd->add_option("--out", a->out,
                  "output folder (CSV, plots, summary.md); default out/accuracy (git ignores out/)");
  cmd->add_option("--models", a->models, "procedural vehicles (with --meshes: use at most this many)")
      ->check(CLI::Range(2u, host::kMaxFleetSize))
      ->each([a](const std::string&) { a->models_given = true; })
      ->capture_default_str();
  cmd->add_option("--meshes", a->meshes, "model meshes (files or folders) instead of the procedural fleet");
  cmd->add_option("--queries-per-model", a->queries_per_model, "queries (random sides and poses) per model")
      ->check(CLI::Range(1u, kMaxQueriesPerModel))
      ->capture_default_str();
  cmd->add_option("--noise", a->noise, "noise levels, m along the ray")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--occlusion", a->occlusion, "occluded fractions")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 0.9))
      ->capture_default_str();
  cmd->add_option("--spacing", a->spacing,
                  "query point spacings, m between rays at the object (0.05: 20 m range)")
      ->delimiter(',')
      ->check(CLI::Range(0.01, 0.5))
      ->capture_default_str();
  cmd->add_option("--ground-slope", a->slopes,
                  "terrain slopes, degrees, under the vehicle in the ground conditions")
      ->delimiter(',')
      ->check(CLI::Range(0.0, host::kMaxGroundSlopeDeg))
      ->capture_default_str();
  cmd->add_option("--lookalikes", a->lookalikes,
                  "look-alike copies of each model added to the database (queries stay on the originals)")
      ->check(CLI::Range(0u, kMaxLookalikesPerModel))
      ->capture_default_str();
  cmd->add_flag("--ground", a->ground, "also run every condition with the ground around the vehicle scanned");
  cmd->add_flag("--ground-kept", a->ground_kept,
                "also run every condition with the ground scanned and the recognizer's ground removal off");
  cmd->add_option("--ground-margin", a->ground_margin, "ground beyond the vehicle on each side, m")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--modes", a->modes, "bran, sran, sind")->delimiter(',')->capture_default_str();
  cmd->add_option("--seed", a->seed, "seed of the query scans")->capture_default_str();
  cmd->add_option("--fleet-seed", a->fleet_seed, "seed of the procedural fleet")->capture_default_str();
  cmd->add_option("--max-k", a->max_k, "largest k of the curves")
      ->check(CLI::Range(1u, 1000u))
      ->capture_default_str();
  cmd->add_option("--ground-clearance", a->ground_clearance,
                  "m above the terrain dropped with it (the recognizer's)")
      ->check(CLI::Range(0.0f, kMaxGroundClearance))
      ->capture_default_str();
  add_bran_knobs(cmd, &a->bran);
  cmd->callback([a, exit_code]() { *exit_code = run_accuracy(*a); });
}

}  // namespace spinhash::experiment
