// The spinhash subcommands. Each registers itself on the app and, when
// chosen, stores its exit status in *exit_code:
//   0 success, 1 error (message on stderr), 3 ran but a check or query failed.
#pragma once
#include <CLI/CLI.hpp>

namespace spinhash::cli {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitCheckFailed = 3;

void add_build_command(CLI::App& app, int* exit_code);
void add_info_command(CLI::App& app, int* exit_code);
void add_verify_command(CLI::App& app, int* exit_code);
void add_scan_command(CLI::App& app, int* exit_code);
void add_recognize_command(CLI::App& app, int* exit_code);
void add_generate_command(CLI::App& app, int* exit_code);
void add_experiment_command(CLI::App& app, int* exit_code);

}  // namespace spinhash::cli
