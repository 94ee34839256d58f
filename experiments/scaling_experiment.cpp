// spinhash-experiment scaling: Figure 10 (time and hypotheses per query
// against database size) with one query set drawn from the models every
// database holds, plus build time and blob size against features.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

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
#include "scaling_data.hpp"
#include "spinhash/limits.hpp"

namespace spinhash::experiment {
namespace {

constexpr uint32_t kQueryPoolModels = 25;  // queries come from the first 25 models (in every database)
constexpr uint32_t kMaxQueries = 10000;

struct ScalingArgs {
  std::string out;
  std::vector<uint32_t> sizes{25, 56, 100, 250, 500, 1000};
  uint32_t queries = 20;
  std::vector<std::string> modes{"bran", "sran", "sind"};
  double noise = 0.05;
  double spacing = kPaperQuerySpacing;  // m between query rays at the object
  std::vector<std::string> meshes;      // instead of the procedural fleet
  uint32_t lookalikes = 0;              // copies of each mesh (with --meshes)
  uint64_t seed = 1;
  uint64_t fleet_seed = 1;
  // SRAN is linear in the models (seconds per query at 1000): at the large
  // sizes it runs on the first few queries only (stated in the summary).
  uint32_t sran_queries_large = 10;
  uint32_t sran_large_from = 250;
  BranKnobs bran;
};

bool make_queries(const ScalingArgs& a, const std::vector<pipeline::ModelMesh>& meshes, uint32_t pool,
                  std::vector<Query>* out, std::string* error) {
  const QueryCondition cond{a.noise, 0.0, Ground::kNone, a.spacing};
  for (uint32_t j = 0; j < a.queries; ++j) {
    Query q;
    if (!simulate_query(meshes[j % pool].mesh, j % pool, j / pool, cond, a.seed, 0.0, &q, error))
      return false;
    out->push_back(std::move(q));
  }
  return true;
}

uint32_t queries_for(const ScalingArgs& a, Mode m, uint32_t size) {
  return m == Mode::kSran && size >= a.sran_large_from ? std::min(a.queries, a.sran_queries_large)
                                                       : a.queries;
}

bool measure_size(const ScalingArgs& a, const std::vector<host::ModelCloud>& all, uint32_t size_index,
                  const std::vector<Query>& queries, ScalingRun* run, std::string* error) {
  const uint32_t size = a.sizes[size_index];
  std::fprintf(stderr, "spinhash-experiment scaling: %u models: building\n", size);
  std::vector<host::ModelCloud> prefix;  // the whole fleet is passed without a copy
  if (size < all.size()) prefix.assign(all.begin(), all.begin() + size);
  std::unique_ptr<MemoryDatabase> mdb =
      build_memory_database(size < all.size() ? prefix : all, host::BuildOptions{}, false, error);
  if (!mdb) return false;
  prefix.clear();
  run->builds.push_back(BuildPoint{size, mdb->db.feature_count(), mdb->build_seconds, mdb->serialize_seconds,
                                   mdb->blob_bytes, mdb->report.max_bucket, mdb->report.mean_bucket});
  run->database = database_text(*mdb);
  for (uint32_t m = 0; m < run->modes.size(); ++m) {
    RecognizerConfig cfg;
    cfg.mode = run->modes[m];
    a.bran.apply(&cfg);
    pipeline::RecognitionSession session;
    if (!session.init(&mdb->db, cfg, error)) return false;
    run->recognizer = recognizer_text(session.config());
    const uint32_t n = queries_for(a, cfg.mode, size);
    pipeline::Progress progress(std::to_string(size) + " models, " + host::mode_name(cfg.mode), n);
    for (uint32_t j = 0; j < n; ++j) {
      run->records.push_back(
          ScalingRecord{size_index, m, j, queries[j].model, recognise(session, queries[j])});
      progress.tick(j + 1);
    }
  }
  return true;
}

// The procedural fleet, or the meshes with their look-alike copies (queries
// then come from the originals); the largest size is capped at what exists.
bool fleet(ScalingArgs& a, std::vector<pipeline::ModelMesh>* meshes, ScalingRun* run, std::string* error) {
  if (a.meshes.empty()) {
    *meshes = generated_models(a.sizes.back(), a.fleet_seed);
    run->source = "procedural fleet (seed " + std::to_string(a.fleet_seed) + ")";
    return true;
  }
  if (!loaded_models(a.meshes, 0u, meshes, error)) return false;
  const uint32_t originals = static_cast<uint32_t>(meshes->size());
  *meshes = with_lookalikes(*meshes, a.lookalikes);
  run->source = std::to_string(originals) + " meshes, each with " + std::to_string(a.lookalikes) +
                " look-alike copies; queries from the originals";
  run->query_pool_cap = originals;
  while (!a.sizes.empty() && a.sizes.back() > meshes->size()) a.sizes.pop_back();
  if (a.sizes.empty() || a.sizes.front() < originals) {
    *error = "every size must hold the " + std::to_string(originals) + " originals and at most " +
             std::to_string(meshes->size()) + " models";
    return false;
  }
  return true;
}

int run_scaling(ScalingArgs a) {
  std::string error;
  ScalingRun run;
  std::sort(a.sizes.begin(), a.sizes.end());
  a.sizes.erase(std::unique(a.sizes.begin(), a.sizes.end()), a.sizes.end());
  run.out_dir = a.out;
  run.command = invoked_command_line();
  run.queries = a.queries;
  run.query_pool = std::min(kQueryPoolModels, a.sizes.front());
  run.spacing = a.spacing;
  run.sran_queries_large = a.sran_queries_large;
  run.sran_large_from = a.sran_large_from;
  run.noise = a.noise;
  std::vector<pipeline::ModelMesh> meshes;
  bool ok = fleet(a, &meshes, &run, &error);
  run.query_pool = std::min(run.query_pool, run.query_pool_cap);
  std::vector<host::ModelCloud> clouds;
  std::vector<Query> queries;
  auto start = std::chrono::steady_clock::now();
  ok = ok && parse_modes(a.modes, &run.modes, &error) && make_output_dir(a.out, &error) &&
       model_clouds(meshes, &clouds, &error);
  run.scan_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ok = ok && make_queries(a, meshes, run.query_pool, &queries, &error);
  meshes.clear();
  for (uint32_t s = 0; ok && s < a.sizes.size(); ++s) ok = measure_size(a, clouds, s, queries, &run, &error);
  if (!ok || !write_scaling_report(run, &error)) {
    std::fprintf(stderr, "spinhash-experiment scaling: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::fprintf(stderr, "spinhash-experiment scaling: wrote %s/summary.md\n", a.out.c_str());
  return pipeline::kExitOk;
}

}  // namespace

void add_scaling_experiment(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<ScalingArgs>();
  CLI::App* cmd =
      parent->add_subcommand("scaling", "Figure 10: time and hypotheses per query against database size");
  a->out = default_output_dir("scaling");
  cmd->add_option("--out", a->out,
                  "output folder (CSV, plots, summary.md); default out/scaling (git ignores out/)");
  cmd->add_option("--sizes", a->sizes, "database sizes (models; the smallest holds every query's model)")
      ->delimiter(',')
      ->check(CLI::Range(2u, host::kMaxFleetSize))
      ->capture_default_str();
  cmd->add_option("--queries", a->queries, "queries, drawn in turn from the first 25 models")
      ->check(CLI::Range(1u, kMaxQueries))
      ->capture_default_str();
  cmd->add_option("--modes", a->modes, "bran, sran, sind")->delimiter(',')->capture_default_str();
  cmd->add_option("--noise", a->noise, "query noise, m along the ray")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--spacing", a->spacing, "query point spacing, m between rays at the object")
      ->check(CLI::Range(0.01, 0.5))
      ->capture_default_str();
  cmd->add_option("--meshes", a->meshes, "model meshes (files or folders) instead of the procedural fleet");
  cmd->add_option("--lookalikes", a->lookalikes, "with --meshes: look-alike copies of each mesh")
      ->check(CLI::Range(0u, kMaxLookalikesPerModel))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "seed of the query scans")->capture_default_str();
  cmd->add_option("--fleet-seed", a->fleet_seed, "seed of the procedural fleet")->capture_default_str();
  cmd->add_option("--sran-queries-large", a->sran_queries_large, "SRAN's queries at the large sizes")
      ->check(CLI::Range(1u, kMaxQueries))
      ->capture_default_str();
  add_bran_knobs(cmd, &a->bran);
  cmd->add_option("--sran-large-from", a->sran_large_from, "sizes from which SRAN runs fewer queries")
      ->capture_default_str();
  cmd->callback([a, exit_code]() { *exit_code = run_scaling(*a); });
}

}  // namespace spinhash::experiment
