// spinhash verify DB.shdb [MESH_OR_DIR...] [--format text|json]: integrity (the core's full
// validation, the calibration's consistency included) and, given the
// meshes, every model recognised first from its own simulated scans and a
// small re-run of the calibration scans against what the blob's calibration
// expects.
#include <cstdio>
#include <memory>

#include "blob/blob_content_of.hpp"
#include "calib/calibration_check.hpp"
#include "calib/calibration_runs.hpp"
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
  uint32_t calibration_scans = 1;      // per model, in the calibration re-run
  uint32_t calibration_left_out = 16;  // models recognised left out in it
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
  std::vector<calib::LevelCheck> calibration;  // the re-run, when made
  std::string calibration_skipped;             // why not, when meshes were given
};

bool fitted(const Database& db) { return db.calibration().fitted(AnswerPass::kFull); }

// "full, first": the passes with a fitted table.
std::string fitted_passes(const Database& db) {
  std::string out;
  for (uint32_t p = 0; p < kAnswerPassCount; ++p)
    if (db.calibration().fitted(static_cast<AnswerPass>(p)))
      out += (out.empty() ? "" : ", ") + std::string(answer_pass_name(p));
  return out;
}

// New calibration runs (the build's seed + 1) of every model against each
// of the blob's fitted passes. Needs a mesh for every model.
bool recheck_calibration(const VerifyArgs& a, const Database& db, const std::vector<ModelMesh>& meshes,
                         VerifyReport* report, std::string* error) {
  std::vector<const host::Mesh*> by_model(db.model_count(), nullptr);
  for (const ModelMesh& m : meshes) {
    const int32_t i = db.find_model(m.name.c_str());
    if (i >= 0) by_model[static_cast<size_t>(i)] = &m.mesh;
  }
  for (const host::Mesh* m : by_model)
    if (m == nullptr) {
      report->calibration_skipped = "not every model has a mesh";
      return true;
    }
  calib::RunSettings runs;
  runs.scans_per_model = a.calibration_scans;
  runs.left_out_scans = a.calibration_scans;
  runs.max_left_out = a.calibration_left_out;
  runs.clutter_scans = std::max(16u, a.calibration_left_out);
  runs.seed = db.calibration().header().seed + 1u;
  runs.clutter = db.calibration().header().clutter;  // the clutter the flags were fitted against
  runs.recognizer = a.config;
  runs.quiet = a.quiet;
  std::vector<host::CalibrationRun> records;
  calib::RunSummary summary;
  if (!calib::run_calibration(host::content_of(db), by_model, runs, &records, &summary, error)) return false;
  for (uint32_t p = 0; p < kAnswerPassCount; ++p) {
    const AnswerPass pass = static_cast<AnswerPass>(p);
    if (!db.calibration().fitted(pass)) continue;
    const std::vector<calib::LevelCheck> checks = calib::check_calibration(db.calibration(), pass, records);
    report->calibration.insert(report->calibration.end(), checks.begin(), checks.end());
  }
  return true;
}

bool calibration_agrees(const VerifyReport& r) {
  for (const calib::LevelCheck& k : r.calibration)
    if (!k.agrees) return false;
  return true;
}

void print_calibration_check(const VerifyReport& r) {
  for (const calib::LevelCheck& k : r.calibration)
    std::printf(
        "calibration  %-5s %-8s %4u flagged, %3u wrong: precision %.4f (expected %.4f), recall %.4f "
        "(expected "
        "%.4f): "
        "%s\n",
        answer_pass_name(static_cast<uint32_t>(k.pass)), answer_level_name(static_cast<uint32_t>(k.level)),
        k.flagged, k.wrong, k.observed_precision, k.expected_precision, k.observed_recall, k.expected_recall,
        k.agrees ? "agrees" : "DISAGREES beyond sampling error");
}

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

std::string check_json(const calib::LevelCheck& c) {
  namespace k = verify_keys;
  return json_object({json_member(k::kPass, json_string(answer_pass_name(static_cast<uint32_t>(c.pass)))),
                      json_member(k::kLevel, json_string(answer_level_name(static_cast<uint32_t>(c.level)))),
                      json_member(k::kFlagged, std::to_string(c.flagged)),
                      json_member(k::kWrong, std::to_string(c.wrong)),
                      json_member(k::kPrecision, json_number(c.observed_precision, 6)),
                      json_member(k::kExpectedPrecision, json_number(c.expected_precision, 6)),
                      json_member(k::kRecall, json_number(c.observed_recall, 6)),
                      json_member(k::kExpectedRecall, json_number(c.expected_recall, 6)),
                      json_member(k::kAgrees, c.agrees ? "true" : "false")});
}

std::string verify_json(const VerifyArgs& a, const Database* db, const VerifyReport& r,
                        const std::string& error) {
  namespace k = verify_keys;
  if (db == nullptr)
    return json_object({json_member(k::kIntegrity, json_string("failed")),
                        json_member(k::kError, json_string(error)), json_version_member()});
  std::vector<std::string> missing, misses, checks;
  for (const std::string& name : r.missing) missing.push_back(json_string(name));
  for (const calib::LevelCheck& c : r.calibration) checks.push_back(check_json(c));
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
       json_member(k::kMisses, json_array(misses)),
       json_member(k::kCalibration, json_string(fitted(*db) ? "fitted" : "priors")),
       json_member(k::kCalibrationCheck, json_array(checks)), json_version_member()});
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
    std::printf(
        "integrity     ok (%u models, %u features, all sections and checksums valid; calibration %s)\n",
        file.db.model_count(), file.db.feature_count(),
        fitted(file.db) ? ("fitted: " + fitted_passes(file.db)).c_str() : "none: the priors decide");
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
  if (!meshes.empty() && fitted(file.db) && !recheck_calibration(a, file.db, meshes, &report, &error)) {
    print_error("verify", error);
    return kExitError;
  }
  if (!report.calibration_skipped.empty())
    std::fprintf(stderr, "spinhash verify: calibration not re-run: %s\n", report.calibration_skipped.c_str());
  if (json) {
    std::printf("%s\n", verify_json(a, &file.db, report, "").c_str());
  } else if (!a.meshes.empty()) {
    std::printf("self-recognition %u/%u scans ranked their own model first (%s, noise %.3g m)\n", report.hits,
                report.scans, mode_name(a.config.mode), a.noise);
    print_calibration_check(report);
  }
  return report.hits == report.scans && report.missing.empty() && calibration_agrees(report)
             ? kExitOk
             : kExitCheckFailed;
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
  cmd->add_option("--calibration-scans", a->calibration_scans,
                  "calibration re-run (a fitted blob, with meshes): scans per model")
      ->check(CLI::Range(1u, 100u))
      ->capture_default_str();
  cmd->add_option("--calibration-left-out", a->calibration_left_out,
                  "calibration re-run: models also recognised with a database built without them")
      ->check(CLI::Range(0u, kMaxModels))
      ->capture_default_str();
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->add_option("--format", a->format, "text, or json: one JSON object on one line")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  add_recognizer_flags(cmd, &a->config);
  cmd->callback([a, exit_code]() { *exit_code = run_verify(*a); });
}

}  // namespace spinhash::cli
