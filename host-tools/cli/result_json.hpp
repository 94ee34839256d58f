// One recognition result as the JSON object of the `recognize` contract.
#pragma once
#include <string>

#include "spinhash/recognizer.hpp"

namespace spinhash::cli {

// Status as a stable snake_case word for machine readers ("ok", "empty_cloud", ...).
const char* status_word(Status s);

// {"query":..,"status":..,"ranking":[{"model":..,"score":..},..],"pose":[16]|null,
//  "confident":..,"group_size":..,"class":..,"class_confident":..,"class_ranking":[..],
//  "time_ms":..,"hypotheses":..} plus "error" when not ok and a "stats" object.

std::string result_json(const std::string& query, const Database& db, const Result& r, uint32_t top,
                        double time_ms);

}  // namespace spinhash::cli
