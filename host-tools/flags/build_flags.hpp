// The feature, LSH, scan and calibration flags of `build` (also used by `experiment`).
#pragma once
#include <CLI/CLI.hpp>

#include "pipeline/build_database_file.hpp"

namespace spinhash::flags {

void add_build_flags(CLI::App* cmd, pipeline::BuildSettings* s);

}  // namespace spinhash::flags
