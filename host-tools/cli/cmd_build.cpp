// spinhash build -o DB.shdb [options] MESH_OR_DIR...
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "flags/build_flags.hpp"
#include "pipeline/build_database_file.hpp"

namespace spinhash::cli {

using flags::add_build_flags;
using pipeline::build_database_file;
using pipeline::BuildSettings;
using pipeline::BuildSummary;
using pipeline::load_model_meshes;
using pipeline::ModelMesh;
namespace {

struct BuildArgs {
  std::string output;
  std::vector<std::string> inputs;
  BuildSettings settings;
};

int run_build(const BuildArgs& a) {
  std::string error;
  std::vector<ModelMesh> meshes;
  BuildSummary summary;
  if (!load_model_meshes(a.inputs, &meshes, &error, a.settings.quiet)) {
    print_error("build", error + "; " + a.output + " not written");
    return kExitError;
  }
  if (!build_database_file(meshes, a.settings, a.output, &summary, &error)) {
    print_error("build", error);
    return kExitError;
  }
  std::fprintf(
      stderr,
      "spinhash build: %s: %u models, %u features, %llu bytes (%.1f bytes/feature), "
      "largest LSH bucket %u, %.1f s\n",
      a.output.c_str(), summary.models, summary.features, static_cast<unsigned long long>(summary.bytes),
      static_cast<double>(summary.bytes) / summary.features, summary.report.max_bucket, summary.seconds);
  if (summary.calibrated)
    std::fprintf(
        stderr,
        "spinhash build: calibrated on %llu runs: %u scans per model, %u models left out (%u scans each), "
        "%u clutter scans, %u threads, %.1f s (spinhash info prints the thresholds)\n",
        static_cast<unsigned long long>(summary.calibration_runs), summary.calibration.drawn.scans_per_model,
        summary.calibration.drawn.models_left_out, summary.calibration.drawn.scans_per_left_out,
        summary.calibration.drawn.clutter_scans, summary.calibration.jobs, summary.calibration.seconds);
  else
    std::fprintf(stderr,
                 "spinhash build: not calibrated (--no-calibration): the recognizer's priors decide\n");
  return kExitOk;
}

}  // namespace

void add_build_command(CLI::App& app, int* exit_code) {
  auto args = std::make_shared<BuildArgs>();
  CLI::App* cmd = app.add_subcommand("build", "build a database blob from meshes (model name = file stem)");
  cmd->add_option("-o,--output", args->output, "database file to write (atomically)")->required();
  cmd->add_option("inputs", args->inputs, "mesh files or directories of meshes")->required();
  add_build_flags(cmd, &args->settings);
  cmd->callback([args, exit_code]() { *exit_code = run_build(*args); });
}

}  // namespace spinhash::cli
