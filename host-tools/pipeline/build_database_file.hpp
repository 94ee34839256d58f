// Meshes -> model clouds -> database content -> blob file, written atomically.
// Shared by `build` and `experiment`.
#pragma once
#include <string>
#include <vector>

#include "blob/byte_order.hpp"
#include "calib/calibration_runs.hpp"
#include "db/calibration_fit.hpp"
#include "db/database_builder.hpp"
#include "pipeline/model_sources.hpp"

namespace spinhash::pipeline {

// The calibration of the answer levels' flags (calib/, db/calibration_fit.hpp).
struct CalibrationSettings {
  bool enabled = true;  // false: the priors decide (a quick database for tests)
  calib::RunSettings runs;
  host::FitOptions fit;
};

struct BuildSettings {
  host::BuildOptions options;
  CalibrationSettings calibration;
  double scan_spacing = 0.05;  // m between model-scan rays at the object
  host::ByteOrder byte_order = host::ByteOrder::kNative;
  std::string class_manifest;  // "MODEL_NAME CLASS [GROUP]" lines (model_classes.hpp); "": folders and names
  bool quiet = false;
};

struct BuildSummary {
  uint32_t models = 0;
  uint32_t features = 0;
  uint64_t bytes = 0;
  double seconds = 0.0;
  host::BuildReport report;
  bool calibrated = false;
  calib::RunSummary calibration;  // when calibrated
  uint64_t calibration_runs = 0;
};

bool build_database_file(const std::vector<ModelMesh>& meshes, const BuildSettings& s,
                         const std::string& out_path, BuildSummary* summary, std::string* error);

}  // namespace spinhash::pipeline
