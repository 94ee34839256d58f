// spinhash experiment accuracy|scaling|lsh|prepare-warzone.
#include "cli/commands.hpp"
#include "experiment/experiments.hpp"

namespace spinhash::cli {

void add_experiment_command(CLI::App& app, int* exit_code) {
  CLI::App* cmd = app.add_subcommand(
      "experiment", "reproduce the paper's experiments: accuracy (Fig. 9), scaling (Fig. 10), LSH (eq. 2)");
  cmd->require_subcommand(1);
  experiment::add_accuracy_experiment(cmd, exit_code);
  experiment::add_scaling_experiment(cmd, exit_code);
  experiment::add_lsh_experiment(cmd, exit_code);
  experiment::add_prepare_warzone(cmd, exit_code);
}

}  // namespace spinhash::cli
