// Recognizer settings on the command line (recognize, verify, scene,
// survey, the experiments): a flag per field that has one (the field lists),
// `--preset`, `--viewpoint`, and `--set KEY=VALUE` for every field
// (config/config_assign.hpp), applied after the flags, in order.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "spinhash/config.hpp"

namespace spinhash::flags {

// Every flag of the field lists, --preset, --viewpoint and --set.
void add_recognizer_flags(CLI::App* cmd, RecognizerConfig* cfg);
// --preset and --set alone (survey: the scene's own flags choose the rest).
void add_set_option(CLI::App* cmd, RecognizerConfig* cfg);

// One KEY=VALUE of --set: "" when it names a field and a valid value, else
// the error (a CLI11 validator).
std::string check_setting(const std::string& setting);
// The KEY=VALUEs in order; a bad one throws CLI::ValidationError("--set").
void apply_settings(const std::vector<std::string>& settings, RecognizerConfig* cfg);

}  // namespace spinhash::flags
