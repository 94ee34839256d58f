// Recognizer settings on the command line (recognize, verify, experiment).
#pragma once
#include <CLI/CLI.hpp>

#include "spinhash/config.hpp"

namespace spinhash::flags {

void add_recognizer_flags(CLI::App* cmd, RecognizerConfig* cfg);

}  // namespace spinhash::flags
