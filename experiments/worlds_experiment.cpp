// spinhash-experiment worlds: leave one world out. For each world of
// vehicle meshes, a database of every other world's vehicles (built as
// `spinhash build` builds) recognises that world's vehicles as unknown
// vehicles, and a database of every world's vehicles recognises the same
// scans with their models in it; scans of non-vehicles are recognised with
// the latter.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "config_text.hpp"
#include "experiments.hpp"
#include "flags/build_flags.hpp"
#include "mesh/vehicle_generator.hpp"
#include "output_dir.hpp"
#include "pipeline/build_database_file.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/version.hpp"
#include "worlds_data.hpp"

namespace spinhash::experiment {
namespace {

constexpr uint32_t kMaxScans = 1000;         // per vehicle or piece of clutter and condition
constexpr uint32_t kMaxThreads = 64;         // recognitions in parallel
constexpr uint32_t kMaxSceneClutter = 1000;  // pieces of each kind

struct WorldsArgs {
  std::string out;
  uint32_t fleet = 56;  // procedural vehicles: the built-in fleet
  uint64_t fleet_seed = 1;
  std::vector<std::string> catalogs;
  std::vector<std::string> clutter_sources{"warzone-structure"};
  uint32_t scene_clutter = 16;          // pieces of each kind
  uint32_t vehicle_sized_clutter = 16;  // pieces of each kind
  std::vector<std::string> conditions{"clean", "ground", "no-ground", "sparse"};
  uint32_t scans_per_world = 120;  // at least, per condition
  uint32_t min_scans = 3;          // per vehicle and condition
  uint32_t clutter_scans = 2;      // per piece of clutter
  uint64_t scan_seed = 1;
  uint32_t threads = 1;
  bool reuse_databases = false;  // open OUT/databases/NAME.shdb when it holds the same models
  pipeline::BuildSettings build;
};

// A database built from `vehicles` (indices into set.vehicles) and opened;
// `to_vehicle` maps its model indices to set.vehicles.
struct OpenDatabase {
  WorldsDatabaseInfo info;
  pipeline::DatabaseFile file;
  std::vector<int32_t> to_vehicle;
};

// Maps the opened database's models to set.vehicles by name (-1: none);
// returns how many were found.
uint32_t map_to_vehicles(const std::map<std::string, int32_t>& index, OpenDatabase* out) {
  const Database& db = out->file.db;
  uint32_t found = 0;
  for (uint32_t m = 0; m < db.model_count(); ++m) {
    const auto it = index.find(pipeline::model_name(db, m));
    out->to_vehicle.push_back(it == index.end() ? -1 : it->second);
    found += it == index.end() ? 0u : 1u;
  }
  return found;
}

// Opens the database already at out->info.path; refused unless its models
// are exactly `index`'s (a database of other vehicles would judge wrongly).
bool reuse_database(const std::map<std::string, int32_t>& index, OpenDatabase* out, std::string* error) {
  if (!pipeline::load_database(out->info.path, &out->file, error)) return false;
  const Database& db = out->file.db;
  if (db.model_count() != index.size() || map_to_vehicles(index, out) != index.size()) {
    *error = out->info.path + ": its models are not the ones this run would build (--reuse-databases)";
    return false;
  }
  out->info.models = db.model_count();
  out->info.features = db.feature_count();
  out->info.bytes = std::filesystem::file_size(out->info.path);
  out->info.seconds = 0.0;  // reused: no build
  return true;
}

bool build_database(const WorldSet& set, const std::vector<uint32_t>& vehicles, const std::string& name,
                    const WorldsArgs& a, OpenDatabase* out, std::string* error) {
  std::vector<pipeline::ModelMesh> meshes;
  std::map<std::string, int32_t> index;
  for (uint32_t v : vehicles) {
    meshes.push_back(set.vehicles[v].model);
    index[set.vehicles[v].model.name] = static_cast<int32_t>(v);
  }
  out->info.name = name;
  out->info.path = a.out + "/databases/" + name + ".shdb";
  if (a.reuse_databases && std::filesystem::exists(out->info.path)) return reuse_database(index, out, error);
  if (!a.build.quiet)
    std::fprintf(stderr, "spinhash-experiment worlds: building %s (%zu models)\n", out->info.path.c_str(),
                 meshes.size());
  pipeline::BuildSummary summary;
  if (!make_output_dir(a.out + "/databases", error) ||
      !pipeline::build_database_file(meshes, a.build, out->info.path, &summary, error) ||
      !pipeline::load_database(out->info.path, &out->file, error))
    return false;
  out->info.models = summary.models;
  out->info.features = summary.features;
  out->info.bytes = summary.bytes;
  out->info.seconds = summary.seconds;
  map_to_vehicles(index, out);
  return true;
}

struct Job {
  bool clutter = false;
  uint32_t object = 0, condition = 0, scan = 0;
};

// Scans a job's object and recognises the scan with each of `dbs`, one
// record each, in `out` (dbs.size() slots).
bool run_job(const WorldSet& set, const WorldsRun& run, const Job& job, uint64_t seed,
             const std::vector<const OpenDatabase*>& dbs, const std::vector<WorldsDatabase>& kinds,
             std::vector<std::unique_ptr<pipeline::RecognitionSession>>& sessions, WorldsRecord* out,
             std::string* error) {
  const uint32_t object_id =
      job.clutter ? static_cast<uint32_t>(set.vehicles.size()) + job.object : job.object;
  const ScanDraw d = draw_scan(run.conditions[job.condition], job.condition, seed, object_id, job.scan);
  ObjectScan scan;
  const bool ok = job.clutter ? scan_object(set.clutter[job.object].mesh, set.clutter[job.object].ground_z, d,
                                            &scan, error)
                              : scan_object(set.vehicles[job.object].model.mesh, 0.0, d, &scan, error);
  if (!ok) return false;
  for (size_t k = 0; k < dbs.size(); ++k) {
    WorldsRecord& r = out[k];
    r.clutter = job.clutter;
    r.object = job.object;
    r.condition = job.condition;
    r.scan = job.scan;
    r.draw = d;
    r.points = static_cast<uint32_t>(scan.xyz.size() / 3);
    r.object_points = scan.object_points;
    r.database = kinds[k];
    const Result res = sessions[k]->recognize(scan.xyz);
    r.ms = sessions[k]->last_ms();
    r.status = res.status;
    r.answer = level_answers(res);
    r.scan_density = res.stats.confidence.scan_density;
    if (r.answer.ranked) r.first = dbs[k]->to_vehicle[r.answer.model];
  }
  return true;
}

// Every job on a.threads threads, each with its own sessions; records in
// job order whatever the threads.
bool run_jobs(const WorldSet& set, const WorldsArgs& a, const std::vector<Job>& jobs,
              const std::vector<const OpenDatabase*>& dbs, const std::vector<WorldsDatabase>& kinds,
              const std::string& stage, WorldsRun* run, std::string* error) {
  const size_t first = run->records.size();
  run->records.resize(first + jobs.size() * dbs.size());
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex mutex;
  pipeline::Progress progress(stage, static_cast<uint32_t>(jobs.size()), a.build.quiet);
  uint32_t done = 0;
  auto worker = [&]() {
    std::vector<std::unique_ptr<pipeline::RecognitionSession>> sessions;
    std::string why;
    for (const OpenDatabase* db : dbs) {
      sessions.push_back(std::make_unique<pipeline::RecognitionSession>());
      if (!sessions.back()->init(&db->file.db, RecognizerConfig{}, &why)) break;
      why.clear();
    }
    for (size_t j; why.empty() && !failed && (j = next++) < jobs.size();) {
      if (!run_job(set, *run, jobs[j], a.scan_seed, dbs, kinds, sessions,
                   &run->records[first + j * dbs.size()], &why))
        break;
      std::lock_guard<std::mutex> lock(mutex);
      progress.tick(++done);
    }
    if (!why.empty()) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failed.exchange(true)) *error = why;
    }
  };
  std::vector<std::thread> threads;
  for (uint32_t t = 1; t < a.threads; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  return !failed;
}

uint32_t scans_per_vehicle(const WorldsArgs& a, size_t vehicles) {
  const uint32_t n =
      static_cast<uint32_t>((a.scans_per_world + vehicles - 1) / std::max<size_t>(vehicles, 1));
  return std::min(std::max(a.min_scans, n), kMaxScans);
}

bool load_worlds(const WorldsArgs& a, WorldSet* set, std::string* error) {
  add_fleet_world(a.fleet, a.fleet_seed, set);
  for (const std::string& c : a.catalogs)
    if (!add_catalog(c, a.clutter_sources, set, error)) return false;
  add_scene_clutter(a.scene_clutter, a.scan_seed, set);
  add_vehicle_sized_clutter(a.vehicle_sized_clutter, a.scan_seed, set);
  return check_world_set(*set, error);
}

bool run_worlds(const WorldsArgs& a, WorldsRun* run, std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  WorldSet set;
  if (!make_output_dir(a.out, error) || !select_conditions(a.conditions, &run->conditions, error) ||
      !load_worlds(a, &set, error))
    return false;
  run->set = &set;
  std::vector<uint32_t> everyone(set.vehicles.size());
  for (uint32_t v = 0; v < everyone.size(); ++v) everyone[v] = v;
  OpenDatabase all;
  if (!build_database(set, everyone, "all", a, &all, error)) return false;
  run->databases.push_back(all.info);
  for (uint32_t w = 0; w < set.worlds.size(); ++w) {
    const std::vector<uint32_t> mine = set.vehicles_of(w);
    std::vector<uint32_t> others;
    std::set_difference(everyone.begin(), everyone.end(), mine.begin(), mine.end(),
                        std::back_inserter(others));
    run->scans_per_vehicle.push_back(scans_per_vehicle(a, mine.size()));
    OpenDatabase without;
    if (!build_database(set, others, "without-" + set.worlds[w], a, &without, error)) return false;
    run->databases.push_back(without.info);
    std::vector<Job> jobs;
    for (uint32_t c = 0; c < run->conditions.size(); ++c)
      for (uint32_t v : mine)
        for (uint32_t s = 0; s < run->scans_per_vehicle.back(); ++s) jobs.push_back(Job{false, v, c, s});
    if (!run_jobs(set, a, jobs, {&without, &all}, {WorldsDatabase::kLeftOut, WorldsDatabase::kAll},
                  set.worlds[w], run, error))
      return false;
  }
  std::vector<Job> clutter_jobs;
  for (uint32_t c = 0; c < run->conditions.size(); ++c) {
    if (run->conditions[c].name != "sparse") continue;
    for (uint32_t o = 0; o < set.clutter.size(); ++o)
      for (uint32_t s = 0; s < a.clutter_scans; ++s) clutter_jobs.push_back(Job{true, o, c, s});
  }
  run->clutter_scans = a.clutter_scans;
  if (!run_jobs(set, a, clutter_jobs, {&all}, {WorldsDatabase::kAll}, "clutter", run, error)) return false;
  pipeline::RecognitionSession probe;
  if (!probe.init(&all.file.db, RecognizerConfig{}, error)) return false;
  run->recognizer = recognizer_text(probe.config());
  run->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!write_worlds_report(*run, error)) return false;
  run->set = nullptr;
  return true;
}

int run_worlds_command(const WorldsArgs& a) {
  WorldsRun run;
  run.out_dir = a.out;
  run.command = invoked_command_line();
  run.version = pipeline::version();
  std::string error;
  if (!run_worlds(a, &run, &error)) {
    std::fprintf(stderr, "spinhash-experiment worlds: %s\n", error.c_str());
    return pipeline::kExitError;
  }
  std::fprintf(stderr, "spinhash-experiment worlds: wrote %s/summary.md (%.0f s)\n", a.out.c_str(),
               run.seconds);
  return pipeline::kExitOk;
}

}  // namespace

void add_worlds_experiment(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<WorldsArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "worlds", "leave one world out: each world's vehicles as unknown vehicles, then with their models in");
  a->out = default_output_dir("worlds");
  cmd->add_option(
      "--out", a->out,
      "output folder (per_scan.csv, summary.md, the databases); default out/worlds (git ignores out/)");
  cmd->add_option("--fleet", a->fleet, "procedural vehicles, the world 'fleet' (0: none)")
      ->check(CLI::Range(0u, host::kMaxFleetSize))
      ->capture_default_str();
  cmd->add_option("--fleet-seed", a->fleet_seed, "seed of the procedural fleet")->capture_default_str();
  cmd->add_option(
      "--catalog", a->catalogs,
      "catalog.csv of a prepared world, or its folder (scripts/prepare-*.sh); a row's world is its "
      "source's first word");
  cmd->add_option("--clutter-source", a->clutter_sources,
                  "catalog sources whose rows without a class are scanned as clutter")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--scene-clutter", a->scene_clutter,
                  "the scene simulator's trees, walls, crates and buildings: pieces of each kind")
      ->check(CLI::Range(0u, kMaxSceneClutter))
      ->capture_default_str();
  cmd->add_option("--vehicle-sized-clutter", a->vehicle_sized_clutter,
                  "sheds, freight containers, bushes and heaps: pieces of each kind")
      ->check(CLI::Range(0u, kMaxSceneClutter))
      ->capture_default_str();
  cmd->add_option("--conditions", a->conditions, "clean, ground, no-ground, sparse")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--scans-per-world", a->scans_per_world,
                  "scans of each world per condition, at least (spread over its vehicles)")
      ->check(CLI::Range(1u, 1000000u))
      ->capture_default_str();
  cmd->add_option("--min-scans", a->min_scans, "scans of each vehicle per condition, at least")
      ->check(CLI::Range(1u, kMaxScans))
      ->capture_default_str();
  cmd->add_option("--clutter-scans", a->clutter_scans, "scans of each piece of clutter (sparse condition)")
      ->check(CLI::Range(0u, kMaxScans))
      ->capture_default_str();
  cmd->add_option("--scan-seed", a->scan_seed, "seed of the scans and the scene clutter")
      ->capture_default_str();
  cmd->add_option("--threads", a->threads, "recognitions in parallel")
      ->check(CLI::Range(1u, kMaxThreads))
      ->capture_default_str();
  cmd->add_flag("--reuse-databases", a->reuse_databases,
                "open the databases an earlier run left in OUT/databases instead of building them (refused "
                "unless each holds the models this run would build); their build time shows as 0");
  flags::add_build_flags(cmd, &a->build);
  cmd->callback([a, exit_code]() { *exit_code = run_worlds_command(*a); });
}

}  // namespace spinhash::experiment
