#include "calib/calibration_runs.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "blob/blob_writer.hpp"
#include "calib/calibration_scans.hpp"
#include "db/leave_one_out.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/recognition_session.hpp"
#include "spinhash/presets.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::calib {
namespace {

constexpr uint32_t kMaxScansPerModel = 32;
constexpr uint32_t kMinScansPerModel = 2;
constexpr uint32_t kMinClutterScans = 32, kMaxClutterScans = 256;

// What every thread shares, read-only but for the progress.
struct Shared {
  Shared(const host::BlobContent& f, const Database& d, const std::vector<const host::Mesh*>& m,
         const RunSettings& s)
      : full(f), db(d), meshes(m), settings(s) {}
  const host::BlobContent& full;
  const Database& db;
  const std::vector<const host::Mesh*>& meshes;
  const RunSettings& settings;
  uint32_t scans = 0, left_out_scans = 0;
  std::vector<bool> leave_out;  // per model
  uint32_t clutter = 0;
  std::atomic<uint32_t> next{0}, done{0};
  std::mutex progress_lock;
  pipeline::Progress* progress = nullptr;
};

// A run of `pass` with r's density and evidence; its rightness is the caller's.
host::CalibrationRun evidence_of(AnswerPass pass, host::RunKind kind, const Result& r) {
  host::CalibrationRun run;
  run.pass = pass;
  run.kind = kind;
  run.density = r.status == Status::kOk ? r.stats.confidence.scan_density : 0.0f;
  for (uint32_t l = 0; l < kCalibratedLevels; ++l)
    run.evidence[l] =
        r.status == Status::kOk ? r.levels[l].evidence : -std::numeric_limits<float>::infinity();
  return run;
}

host::CalibrationRun record(AnswerPass pass, host::RunKind kind, const Result& r, int64_t model,
                            uint32_t vehicle_class, uint32_t group) {
  host::CalibrationRun run = evidence_of(pass, kind, r);
  judge(r, kind == host::RunKind::kClutter, model, vehicle_class, group, run.right);
  return run;
}

// One recogniser per calibrated pass over one database: the full pass
// alone (the cascade off) and the cascade's first pass alone.
struct PassSessions {
  pipeline::RecognitionSession full, first;

  bool init(const Database* db, const RecognizerConfig& settings, std::string* error) {
    RecognizerConfig full_pass = settings;
    full_pass.cascade = false;
    RecognizerConfig first_pass;
    apply_first_pass(settings, &first_pass);
    return full.init(db, full_pass, error) && first.init(db, first_pass, error);
  }
  // Both passes' records of one scan, and the agree record of the pair.
  void recognize(host::RunKind kind, const std::vector<double>& xyz, int64_t model, uint32_t vehicle_class,
                 uint32_t group, std::vector<host::CalibrationRun>* out) {
    const Result full_result = full.recognize(xyz);
    const Result first_result = first.recognize(xyz);
    out->push_back(record(AnswerPass::kFull, kind, full_result, model, vehicle_class, group));
    out->push_back(record(AnswerPass::kFirst, kind, first_result, model, vehicle_class, group));
    out->push_back(agree_record(kind, first_result, full_result, model, vehicle_class, group));
  }
};

// The scans of model m: known runs, and unknown ones when it is left out.
bool run_model(Shared& sh, PassSessions& known, uint32_t m, std::vector<host::CalibrationRun>* out,
               std::string* error) {
  host::AlignedBytes bytes;
  Database lomo;
  PassSessions unknown;
  if (sh.leave_out[m]) {
    host::BlobContent content;
    if (!host::without_model(sh.full, m, &content) || !host::open_content(content, &bytes, &lomo, error) ||
        !unknown.init(&lomo, sh.settings.recognizer, error)) {
      if (error->empty()) *error = "the database cannot leave a model out";
      return false;
    }
  }
  const blob::ModelRecord& truth = sh.full.models[m];
  const uint32_t vehicle_class = truth.vehicle_class, group = static_cast<uint32_t>(model_group(truth));
  std::vector<double> xyz;
  const uint32_t scans = sh.leave_out[m] ? sh.left_out_scans : sh.scans;
  for (uint32_t s = 0; s < scans; ++s) {
    if (!scan_vehicle(*sh.meshes[m], draw_scan(sh.settings.seed, m, s), &xyz, error)) return false;
    if (s < sh.scans) known.recognize(host::RunKind::kKnown, xyz, m, vehicle_class, group, out);
    if (sh.leave_out[m]) unknown.recognize(host::RunKind::kUnknown, xyz, -1, vehicle_class, group, out);
  }
  return true;
}

bool run_clutter(Shared& sh, PassSessions& known, uint32_t c, std::vector<host::CalibrationRun>* out,
                 std::string* error) {
  const uint32_t object = static_cast<uint32_t>(sh.meshes.size()) + c;
  std::vector<double> xyz;
  const uint32_t kinds = clutter_kinds_scanned(sh.settings.clutter);
  if (!scan_clutter(static_cast<ClutterKind>(c % kinds), draw_scan(sh.settings.seed, object, 0), &xyz, error))
    return false;
  known.recognize(host::RunKind::kClutter, xyz, -1, 0u, 0u, out);
  return true;
}

void work(Shared& sh, std::vector<std::vector<host::CalibrationRun>>* results,
          std::vector<std::string>* errors) {
  PassSessions known;
  const uint32_t models = static_cast<uint32_t>(sh.meshes.size());
  const uint32_t items = models + sh.clutter;
  std::string init_error;
  const bool ready = known.init(&sh.db, sh.settings.recognizer, &init_error);
  for (uint32_t i = sh.next++; i < items; i = sh.next++) {
    std::string& error = (*errors)[i];
    if (!ready)
      error = init_error;
    else if (i < models)
      run_model(sh, known, i, &(*results)[i], &error);
    else
      run_clutter(sh, known, i - models, &(*results)[i], &error);
    const uint32_t done = ++sh.done;
    std::lock_guard<std::mutex> hold(sh.progress_lock);
    sh.progress->tick(done);
  }
}

}  // namespace

uint32_t default_scans_per_model(uint32_t models) {
  if (models == 0u) return kMaxScansPerModel;
  return std::clamp(kKnownRunsWanted / models, kMinScansPerModel, kMaxScansPerModel);
}

uint32_t left_out_scans(uint32_t scans_per_model, uint32_t left_out) {
  if (left_out == 0u) return scans_per_model;
  const uint32_t wanted = std::min((kUnknownRunsWanted + left_out - 1u) / left_out, kMaxScansPerModel);
  return std::max(scans_per_model, wanted);
}

uint32_t default_clutter_scans(uint32_t unknown_runs) {
  return std::clamp(unknown_runs / 8u, kMinClutterScans, kMaxClutterScans);
}

std::vector<uint32_t> left_out_models(const std::vector<blob::ModelRecord>& models, uint32_t max) {
  const uint32_t n = static_cast<uint32_t>(models.size());
  std::vector<uint32_t> out;
  if (n < 2u) return out;  // nothing would be left to recognise with
  if (n <= max) {
    for (uint32_t m = 0; m < n; ++m) out.push_back(m);
    return out;
  }
  std::vector<std::vector<uint32_t>> members(kVehicleClassCount);
  for (uint32_t m = 0; m < n; ++m) members[models[m].vehicle_class % kVehicleClassCount].push_back(m);
  // Largest remainder, after one each for as many classes as `max` allows.
  std::vector<uint32_t> take(kVehicleClassCount, 0u);
  uint32_t given = 0;
  for (uint32_t c = 0; c < kVehicleClassCount && given < max; ++c)
    if (!members[c].empty()) take[c] = 1u, ++given;
  std::vector<std::pair<double, uint32_t>> remainders;
  const uint32_t left = max - given;
  uint32_t shared = 0;
  for (uint32_t c = 0; c < kVehicleClassCount; ++c) {
    if (take[c] == 0u) continue;
    const double want = static_cast<double>(left) * (members[c].size() - 1u) / (n - given);
    const uint32_t whole =
        std::min(static_cast<uint32_t>(want), static_cast<uint32_t>(members[c].size()) - 1u);
    take[c] += whole;
    shared += whole;
    remainders.push_back({want - whole, c});
  }
  std::stable_sort(remainders.begin(), remainders.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (size_t k = 0; shared < left && k < remainders.size(); ++k) {
    const uint32_t c = remainders[k].second;
    if (take[c] < members[c].size()) ++take[c], ++shared;
  }
  for (uint32_t c = 0; c < kVehicleClassCount; ++c) {
    const size_t size = members[c].size();
    for (uint32_t k = 0; k < take[c]; ++k)
      out.push_back(members[c][static_cast<size_t>((k + 0.5) * size / take[c])]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void judge(const Result& r, bool clutter, int64_t model, uint32_t vehicle_class, uint32_t group,
           bool right[kCalibratedLevels]) {
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) right[l] = false;
  if (clutter) return;
  right[level_index(AnswerLevel::kVehicle)] = true;
  if (r.status != Status::kOk) return;
  if (r.group_ranking_count > 0u) right[level_index(AnswerLevel::kGroup)] = r.group_ranking[0].group == group;
  if (r.class_ranking_count > 0u)
    right[level_index(AnswerLevel::kClass)] = r.class_ranking[0].vehicle_class == vehicle_class;
  if (r.ranking_count > 0u && model >= 0)
    right[level_index(AnswerLevel::kModel)] = static_cast<int64_t>(r.ranking[0].model) == model;
}

host::CalibrationRun agree_record(host::RunKind kind, const Result& first, const Result& full, int64_t model,
                                  uint32_t vehicle_class, uint32_t group) {
  host::CalibrationRun run = evidence_of(AnswerPass::kAgree, kind, first);
  const bool clutter = kind == host::RunKind::kClutter;
  bool first_right[kCalibratedLevels], full_right[kCalibratedLevels];
  judge(first, clutter, model, vehicle_class, group, first_right);
  judge(full, clutter, model, vehicle_class, group, full_right);
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) run.right[l] = first_right[l] || !full_right[l];
  return run;
}

bool run_calibration(const host::BlobContent& full, const std::vector<const host::Mesh*>& meshes,
                     const RunSettings& settings, std::vector<host::CalibrationRun>* runs,
                     RunSummary* summary, std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  if (meshes.size() != full.models.size()) {
    *error = "calibration: " + std::to_string(meshes.size()) + " meshes for " +
             std::to_string(full.models.size()) + " models";
    return false;
  }
  host::AlignedBytes bytes;
  Database db;
  if (!host::open_content(full, &bytes, &db, error)) return false;
  const uint32_t models = static_cast<uint32_t>(meshes.size());
  Shared sh(full, db, meshes, settings);
  sh.scans = settings.scans_per_model > 0u ? settings.scans_per_model : default_scans_per_model(models);
  sh.leave_out.assign(models, false);
  const std::vector<uint32_t> out = left_out_models(full.models, settings.max_left_out);
  for (uint32_t m : out) sh.leave_out[m] = true;
  sh.left_out_scans = settings.left_out_scans > 0u
                          ? std::max(settings.left_out_scans, sh.scans)
                          : left_out_scans(sh.scans, static_cast<uint32_t>(out.size()));
  sh.clutter = settings.clutter_scans > 0u
                   ? settings.clutter_scans
                   : default_clutter_scans(static_cast<uint32_t>(out.size()) * sh.left_out_scans);
  const uint32_t items = models + sh.clutter;
  uint32_t jobs = settings.jobs > 0u ? settings.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = std::min(jobs, items);
  pipeline::Progress progress("calibration", items, settings.quiet);
  sh.progress = &progress;
  std::vector<std::vector<host::CalibrationRun>> results(items);
  std::vector<std::string> errors(items);
  std::vector<std::thread> threads;
  for (uint32_t t = 0; t < jobs; ++t) threads.emplace_back(work, std::ref(sh), &results, &errors);
  for (std::thread& t : threads) t.join();
  for (uint32_t i = 0; i < items; ++i)
    if (!errors[i].empty()) {
      *error = errors[i];
      return false;
    }
  runs->clear();
  for (const auto& r : results) runs->insert(runs->end(), r.begin(), r.end());
  summary->drawn.scans_per_model = sh.scans;
  summary->drawn.scans_per_left_out = sh.left_out_scans;
  summary->drawn.models_left_out = static_cast<uint32_t>(out.size());
  summary->drawn.clutter_scans = sh.clutter;
  summary->drawn.seed = settings.seed;
  summary->drawn.clutter = settings.clutter;
  summary->jobs = jobs;
  summary->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

}  // namespace spinhash::calib
