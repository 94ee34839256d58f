// One recognition result as the JSON object of the `recognize` contract.
#pragma once
#include <string>

#include "spinhash/recognizer.hpp"

namespace spinhash::cli {

// Status as a stable snake_case word for machine readers ("ok", "empty_cloud", ...).
const char* status_word(Status s);

// {"query":..,"status":..,"ranking":[{"model":..,"score":..},..],"pose":[16]|null,
//  "confident":..,"group_size":..,"class":..,"class_confident":..,"class_ranking":[..],
//  "group":..,"group_ranking":[..],"levels":{..},"level":..,
//  "time_ms":..,"hypotheses":..} plus "error" when not ok and a "stats" object.

// crs: the query file's coordinate reference system (the pose's
// translation is in it), as Crs::describe() names it; "" writes null.
std::string result_json(const std::string& query, const Database& db, const Result& r, uint32_t top,
                        double time_ms, const std::string& crs = "");

}  // namespace spinhash::cli
