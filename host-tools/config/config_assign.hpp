// One recognizer setting by its field name ("max_bucket_scan=512"), for
// tools that sweep settings without a flag of their own: the experiments'
// --set and the instruction benchmark's target runner
// (tests/worst_case/worst_case_runner.cpp), which has no CLI11. Names, kinds
// and ranges come from SPINHASH_CONFIG_FIELDS; only numbers and booleans
// (MODE and VEC3D fields have their own flags).
#pragma once
#include <string>

#include "spinhash/config.hpp"

namespace spinhash::host {

// "name=value": sets cfg->name; false with *error naming the problem when the
// name is unknown, the value does not parse or lies outside the field's range.
// "preset=NAME" sets the fields of a named configuration (spinhash/presets.hpp).
bool assign_config_field(const std::string& assignment, RecognizerConfig* cfg, std::string* error);

}  // namespace spinhash::host
