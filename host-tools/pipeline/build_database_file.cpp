#include "pipeline/build_database_file.hpp"

#include <chrono>
#include <map>

#include "blob/blob_writer.hpp"
#include "blob/file_io.hpp"
#include "pipeline/model_classes.hpp"
#include "pipeline/progress.hpp"

namespace spinhash::pipeline {
namespace {

void report_progress(uint32_t done, uint32_t /*total*/, void* user) {
  static_cast<Progress*>(user)->tick(done);
}

// Runs the calibration scans of every model and fits the section from them.
bool calibrate(const std::vector<ModelMesh>& meshes, const CalibrationSettings& s, bool quiet,
               host::BlobContent* content, BuildSummary* summary, std::string* error) {
  std::vector<const host::Mesh*> models;
  for (const ModelMesh& m : meshes) models.push_back(&m.mesh);
  calib::RunSettings runs = s.runs;
  runs.quiet = quiet;
  std::vector<host::CalibrationRun> records;
  if (!calib::run_calibration(*content, models, runs, &records, &summary->calibration, error)) return false;
  if (!host::fit_calibration(records, s.fit, summary->calibration.drawn, &content->calibration, error))
    return false;
  summary->calibrated = true;
  summary->calibration_runs = records.size();
  return true;
}

}  // namespace

bool build_database_file(const std::vector<ModelMesh>& meshes, const BuildSettings& s,
                         const std::string& out_path, BuildSummary* summary, std::string* error) {
  auto start = std::chrono::steady_clock::now();
  std::vector<host::ModelCloud> clouds;
  if (!scan_models(meshes, s.scan_spacing, &clouds, error, s.quiet)) return false;
  if (!s.class_manifest.empty() && !apply_class_manifest(s.class_manifest, &clouds, error)) return false;
  host::BlobContent content;
  Progress progress("features", static_cast<uint32_t>(clouds.size()), s.quiet);
  if (!host::build_database(clouds, s.options, &content, &summary->report, error, report_progress, &progress))
    return false;
  if (s.calibration.enabled && !calibrate(meshes, s.calibration, s.quiet, &content, summary, error))
    return false;
  std::vector<uint8_t> bytes;
  if (!host::serialize_blob(content, s.byte_order, &bytes, error)) return false;
  if (!host::write_file_atomically(out_path, bytes, error)) return false;
  summary->models = content.params.model_count;
  summary->features = content.params.feature_count;
  summary->bytes = bytes.size();
  summary->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

}  // namespace spinhash::pipeline
