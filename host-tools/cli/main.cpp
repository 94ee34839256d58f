// spinhash: build, inspect and verify recognition databases, simulate scans,
// and recognise vehicles in point clouds (contract: docs/cli.md).
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "pipeline/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"spinhash: 3D vehicle recognition in airborne lidar (spin images, LSH, batch RANSAC)"};
  app.set_version_flag("--version", spinhash::pipeline::version());
  app.require_subcommand(1);
  int exit_code = spinhash::cli::kExitOk;
  spinhash::cli::add_build_command(app, &exit_code);
  spinhash::cli::add_info_command(app, &exit_code);
  spinhash::cli::add_verify_command(app, &exit_code);
  spinhash::cli::add_scan_command(app, &exit_code);
  spinhash::cli::add_recognize_command(app, &exit_code);
  spinhash::cli::add_generate_command(app, &exit_code);
  spinhash::cli::add_scene_command(app, &exit_code);
  spinhash::cli::add_scan_scene_command(app, &exit_code);
  spinhash::cli::add_survey_command(app, &exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return spinhash::pipeline::usage_exit_code(app.exit(e));
  }
  return exit_code;
}
