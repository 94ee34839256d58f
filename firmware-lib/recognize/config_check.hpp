// Whether a RecognizerConfig is valid: every field of config_fields.h and
// stage_fields.h within its range, and the rules that join two fields.
#pragma once
#include "spinhash/config.hpp"

namespace spinhash {

bool config_valid(const RecognizerConfig& c);

}  // namespace spinhash
