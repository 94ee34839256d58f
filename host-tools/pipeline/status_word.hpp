// A Status as the stable snake_case word of the JSON output ("ok",
// "empty_cloud", ...): shared by the CLI and the Python module.
#pragma once

#include "spinhash/status.hpp"

namespace spinhash::pipeline {

const char* status_word(Status s);

}  // namespace spinhash::pipeline
