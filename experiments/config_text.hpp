// One-line descriptions of the settings an experiment ran with (the library
// defaults at the time of the run), for the summaries.
#pragma once
#include <string>

#include "memory_database.hpp"
#include "spinhash/config.hpp"

namespace spinhash::experiment {

std::string database_text(const MemoryDatabase& m);
std::string recognizer_text(const RecognizerConfig& c);

}  // namespace spinhash::experiment
