// Recognizer settings on the command line (recognize, verify, experiment).
#pragma once
#include <CLI/CLI.hpp>

#include "spinhash/config.hpp"

namespace spinhash::pipeline {

void add_recognizer_flags(CLI::App* cmd, RecognizerConfig* cfg);
const char* mode_name(Mode m);

}  // namespace spinhash::pipeline
