// spinhash verify DB.shdb [MESH_OR_DIR...] [--format text|json]: integrity (the core's full
// validation) and, given the meshes, every model recognised first from its
// own simulated scans.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cli/json_line.hpp"
#include "cli/report_keys.hpp"
#include "cli/result_json.hpp"
#include "config/mode_name.hpp"
#include "flags/recognizer_flags.hpp"
#include "pipeline/database_file.hpp"
#include "pipeline/model_sources.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/recognition_session.hpp"
#include "scan/scan_simulator.hpp"

namespace spinhash::cli {

using flags::add_recognizer_flags;
using host::mode_name;
using pipeline::DatabaseFile;
using pipeline::load_database;
using pipeline::load_model_meshes;
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
  std::string format = "text";
  RecognizerConfig config;
};

// One self-recognition scan whose own model was not ranked first.
struct Miss {
  std::string model;
  uint32_t scan = 0;
  std::string ranked_first;  // empty when recognition failed or found nothing
  std::string status;        // "ok" (another model first), "no_hypothesis" or the failure's status word
};

struct VerifyReport {
  uint32_t scans = 0, hits = 0;
  std::vector<std::string> missing;  // meshes whose model is not in the database
  std::vector<Miss> misses;
};

// Scans `m` `queries` times from random sides and poses; counts top-1 hits.
void self_recognise(const VerifyArgs& a, const ModelMesh& m, const Database& db, RecognitionSession& s,
                    uint32_t model_index, VerifyReport* report) {
  for (uint32_t q = 0; q < a.queries; ++q) {
    host::ScanOptions opt = host::query_scan_options(a.noise, a.scan_seed + 7919ull * model_index + q);
    opt.random_pose = true;
    host::ScanResult scan = host::simulate_scan(m.mesh, opt);
    Result r = s.recognize(scan.xyz);
    ++report->scans;
    if (r.status == Status::kOk && r.ranking_count > 0 && r.ranking[0].model == model_index) {
      ++report->hits;
      continue;
    }
    const bool ranked = r.status == Status::kOk && r.ranking_count > 0;
    Miss miss{m.name, q, ranked ? model_name(db, r.ranking[0].model) : "",
              r.status != Status::kOk ? status_word(r.status)
              : ranked                ? "ok"
                                      : "no_hypothesis"};
    std::fprintf(stderr, "spinhash verify: %s scan %u: %s\n", m.name.c_str(), q,
                 r.status != Status::kOk     ? status_name(r.status)
                 : miss.ranked_first.empty() ? "no hypothesis"
                                             : ("ranked first: " + miss.ranked_first).c_str());
    report->misses.push_back(miss);
  }
}

std::string verify_json(const VerifyArgs& a, const Database* db, const VerifyReport& r,
                        const std::string& error) {
  namespace k = verify_keys;
  if (db == nullptr)
    return json_object({json_member(k::kIntegrity, json_string("failed")),
                        json_member(k::kError, json_string(error)), json_version_member()});
  std::vector<std::string> missing, misses;
  for (const std::string& name : r.missing) missing.push_back(json_string(name));
  for (const Miss& m : r.misses)
    misses.push_back(json_object(
        {json_member(k::kModel, json_string(m.model)), json_member(k::kScan, std::to_string(m.scan)),
         json_member(k::kRankedFirst, m.ranked_first.empty() ? "null" : json_string(m.ranked_first)),
         json_member(k::kStatus, json_string(m.status))}));
  return json_object(
      {json_member(k::kIntegrity, json_string("ok")),
       json_member(k::kModels, std::to_string(db->model_count())),
       json_member(k::kFeatures, std::to_string(db->feature_count())),
       json_member(k::kMode, json_string(mode_name(a.config.mode))),
       json_member(k::kNoise, json_number(a.noise, 6)), json_member(k::kScans, std::to_string(r.scans)),
       json_member(k::kHits, std::to_string(r.hits)), json_member(k::kMissing, json_array(missing)),
       json_member(k::kMisses, json_array(misses)), json_version_member()});
}

int run_verify(const VerifyArgs& a) {
  DatabaseFile file;
  std::string error;
  const bool json = a.format == "json";
  VerifyReport report;
  if (!load_database(a.db_path, &file, &error)) {
    std::fprintf(stderr, "spinhash verify: %s\n", error.c_str());
    if (json) std::printf("%s\n", verify_json(a, nullptr, report, error).c_str());
    return kExitError;
  }
  if (!json)
    std::printf("integrity     ok (%u models, %u features, all sections and checksums valid)\n",
                file.db.model_count(), file.db.feature_count());
  std::vector<ModelMesh> meshes;
  RecognitionSession session;
  if (!a.meshes.empty() &&
      (!load_model_meshes(a.meshes, &meshes, &error, a.quiet) || !session.init(&file.db, a.config, &error))) {
    print_error("verify", error);
    return kExitError;
  }
  Progress progress("verify", static_cast<uint32_t>(meshes.size()), a.quiet);
  for (size_t i = 0; i < meshes.size(); ++i) {
    int32_t index = file.db.find_model(meshes[i].name.c_str());
    if (index < 0) {
      std::fprintf(stderr, "spinhash verify: %s is not in the database\n", meshes[i].name.c_str());
      report.missing.push_back(meshes[i].name);
    } else {
      self_recognise(a, meshes[i], file.db, session, static_cast<uint32_t>(index), &report);
    }
    progress.tick(static_cast<uint32_t>(i + 1));
  }
  if (json)
    std::printf("%s\n", verify_json(a, &file.db, report, "").c_str());
  else if (!a.meshes.empty())
    std::printf("self-recognition %u/%u scans ranked their own model first (%s, noise %.3g m)\n", report.hits,
                report.scans, mode_name(a.config.mode), a.noise);
  return report.hits == report.scans && report.missing.empty() ? kExitOk : kExitCheckFailed;
}

}  // namespace

void add_verify_command(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand("verify", "check a database's integrity and self-recognition");
  cmd->add_option("database", a->db_path, "database file")->required()->check(CLI::ExistingFile);
  cmd->add_option("meshes", a->meshes, "the model meshes, to recognise each from its own scans");
  cmd->add_option("--queries", a->queries, "scans per model")
      ->check(CLI::Range(1u, 100u))
      ->capture_default_str();
  cmd->add_option("--noise", a->noise, "scan noise along the ray, m")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--scan-seed", a->scan_seed, "seed of the verification scans")->capture_default_str();
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->add_option("--format", a->format, "text, or json: one JSON object on one line")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  add_recognizer_flags(cmd, &a->config);
  cmd->callback([a, exit_code]() { *exit_code = run_verify(*a); });
}

}  // namespace spinhash::cli
