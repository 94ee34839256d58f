// One recognizer setting by its key ("candidates.max_bucket_scan=512"), for
// `--set` on the command line and in the experiments, and for the
// instruction benchmark's target runner (tests/worst_case/worst_case_runner.cpp),
// which has no CLI11. Keys, kinds and ranges come from the field lists
// (config/field_table.hpp): a stage's field as stage.field, or by its
// Python name (the field's own name, unique across the stages; a stage's
// switch <stage>_enabled); a top-level field by its name. Only numbers and
// booleans (MODE and VEC3D fields have their own flags).
#pragma once
#include <string>

#include "spinhash/config.hpp"

namespace spinhash::host {

// "key=value": sets the field; false with *error naming the problem when the
// key is unknown, the value does not parse or lies outside the field's
// range. "preset=NAME" sets the fields of a named configuration
// (spinhash/presets.hpp). BOOL values: 0, 1, false or true.
bool assign_config_field(const std::string& assignment, RecognizerConfig* cfg, std::string* error);

}  // namespace spinhash::host
