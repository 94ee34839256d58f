// spinhash verify DB.shdb [MESH_OR_DIR...]: integrity (the core's full
// validation) and, given the meshes, every model recognised first from its
// own simulated scans.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/model_sources.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/recognizer_flags.hpp"
#include "scan/scan_simulator.hpp"

namespace spinhash::cli {

using pipeline::add_recognizer_flags;
using pipeline::DatabaseFile;
using pipeline::load_database;
using pipeline::load_model_meshes;
using pipeline::mode_name;
using pipeline::model_name;
using pipeline::ModelMesh;
using pipeline::Progress;
using pipeline::RecognitionSession;
namespace {

struct VerifyArgs {
  std::string db_path;
  std::vector<std::string> meshes;
  uint32_t queries = 2;  // scans per model
  double noise = 0.05;   // m along the ray
  uint64_t scan_seed = 1;
  bool quiet = false;
  RecognizerConfig config;
};

// Scans `m` `queries` times from random sides and poses; counts top-1 hits.
uint32_t self_recognise(const VerifyArgs& a, const ModelMesh& m, const Database& db, RecognitionSession& s,
                        uint32_t model_index) {
  uint32_t hits = 0;
  for (uint32_t q = 0; q < a.queries; ++q) {
    host::ScanOptions opt = host::query_scan_options(a.noise, a.scan_seed + 7919ull * model_index + q);
    opt.random_pose = true;
    host::ScanResult scan = host::simulate_scan(m.mesh, opt);
    Result r = s.recognize(scan.xyz);
    bool hit = r.status == Status::kOk && r.ranking_count > 0 && r.ranking[0].model == model_index;
    hits += hit ? 1u : 0u;
    if (!hit)
      std::fprintf(stderr, "spinhash verify: %s scan %u: %s\n", m.name.c_str(), q,
                   r.status != Status::kOk ? status_name(r.status)
                   : r.ranking_count == 0  ? "no hypothesis"
                                           : ("ranked first: " + model_name(db, r.ranking[0].model)).c_str());
  }
  return hits;
}

int run_verify(const VerifyArgs& a) {
  DatabaseFile file;
  std::string error;
  if (!load_database(a.db_path, &file, &error)) {
    std::fprintf(stderr, "spinhash verify: %s\n", error.c_str());
    return kExitError;
  }
  std::printf("integrity     ok (%u models, %u features, all sections and checksums valid)\n",
              file.db.model_count(), file.db.feature_count());
  if (a.meshes.empty()) return kExitOk;
  std::vector<ModelMesh> meshes;
  RecognitionSession session;
  if (!load_model_meshes(a.meshes, &meshes, &error, a.quiet) || !session.init(&file.db, a.config, &error)) {
    std::fprintf(stderr, "spinhash verify: %s\n", error.c_str());
    return kExitError;
  }
  uint32_t hits = 0, total = 0, missing = 0;
  Progress progress("verify", static_cast<uint32_t>(meshes.size()), a.quiet);
  for (size_t i = 0; i < meshes.size(); ++i) {
    int32_t index = file.db.find_model(meshes[i].name.c_str());
    if (index < 0) {
      std::fprintf(stderr, "spinhash verify: %s is not in the database\n", meshes[i].name.c_str());
      ++missing;
    } else {
      hits += self_recognise(a, meshes[i], file.db, session, static_cast<uint32_t>(index));
      total += a.queries;
    }
    progress.tick(static_cast<uint32_t>(i + 1));
  }
  std::printf("self-recognition %u/%u scans ranked their own model first (%s, noise %.3g m)\n", hits, total,
              mode_name(a.config.mode), a.noise);
  return hits == total && missing == 0 ? kExitOk : kExitCheckFailed;
}

}  // namespace

void add_verify_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand("verify", "check a database's integrity and self-recognition");
  cmd->add_option("database", a->db_path, "database file")->required();
  cmd->add_option("meshes", a->meshes, "the model meshes, to recognise each from its own scans");
  cmd->add_option("--queries", a->queries, "scans per model")
      ->check(CLI::Range(1u, 100u))
      ->capture_default_str();
  cmd->add_option("--noise", a->noise, "scan noise along the ray, m")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--scan-seed", a->scan_seed, "seed of the verification scans")->capture_default_str();
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  add_recognizer_flags(cmd, &a->config);
  cmd->callback([a, exit_code]() { *exit_code = run_verify(*a); });
}

}  // namespace spinhash::cli
