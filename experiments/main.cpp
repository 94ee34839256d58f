// spinhash-experiment: the paper's experiments (section 10) and the
// measurements behind docs/results.md. Research tooling, kept out of the
// shipped spinhash command; built on the host pipeline (host-tools/pipeline).
#include <CLI/CLI.hpp>

#include "experiments.hpp"
#include "pipeline/exit_codes.hpp"
#include "pipeline/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "spinhash-experiment: reproduce the paper's experiments: accuracy (Fig. 9), scaling (Fig. 10), LSH "
      "(eq. 2), scene tiles"};
  app.set_version_flag("--version", spinhash::pipeline::version());
  app.require_subcommand(1);
  int exit_code = spinhash::pipeline::kExitOk;
  spinhash::experiment::add_accuracy_experiment(&app, &exit_code);
  spinhash::experiment::add_scaling_experiment(&app, &exit_code);
  spinhash::experiment::add_lsh_experiment(&app, &exit_code);
  spinhash::experiment::add_scene_experiment(&app, &exit_code);
  spinhash::experiment::add_stream_experiment(&app, &exit_code);
  spinhash::experiment::add_worlds_experiment(&app, &exit_code);
  spinhash::experiment::add_prepare_warzone(&app, &exit_code);
  spinhash::experiment::add_prepare_cars(&app, &exit_code);
  spinhash::experiment::add_prepare_sweethome3d(&app, &exit_code);
  spinhash::experiment::add_laz_speed(&app, &exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return spinhash::pipeline::usage_exit_code(app.exit(e));
  }
  return exit_code;
}
