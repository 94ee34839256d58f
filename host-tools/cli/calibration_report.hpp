// The Calibration section as `spinhash info` prints it (text and JSON).
#pragma once
#include <string>

#include "spinhash/calibration.hpp"

namespace spinhash::cli {

// "fitted", "too_few_runs", ... of a cell's state (blob::CalibrationState).
const char* cell_state_word(uint32_t state);

// One line of provenance, then per pass, level and density band the
// threshold and what the fit expects of it.
void print_calibration(const Calibration& c);

// The same as one JSON object (info_keys).
std::string calibration_json(const Calibration& c);

}  // namespace spinhash::cli
