// Conversion between the C structs (spinhash.h) and the C++ config and
// statistics, produced from the field lists in spinhash/config_fields.h;
// tests/core/test_c_api.cpp checks the round trip of every field.
#pragma once
#include "spinhash/config.hpp"
#include "spinhash/recognizer.hpp"
#include "spinhash/spinhash.h"

namespace spinhash {

void to_c_config(const RecognizerConfig& in, spinhash_config* out) noexcept;
// false when the C config holds a mode that does not exist.
bool from_c_config(const spinhash_config& in, RecognizerConfig* out) noexcept;
void to_c_stats(const RecognitionStats& in, spinhash_stats* out) noexcept;

}  // namespace spinhash
