// Field-by-field conversion between the C config (spinhash.h) and
// spinhash::RecognizerConfig. A field added to one must be added here and to
// the C struct (appended); tests/core/test_c_api.cpp checks the round trip.
#pragma once
#include "spinhash/config.hpp"
#include "spinhash/spinhash.h"

namespace spinhash {

void to_c_config(const RecognizerConfig& in, spinhash_config* out) noexcept;
// false when the C config holds a mode that does not exist.
bool from_c_config(const spinhash_config& in, RecognizerConfig* out) noexcept;

}  // namespace spinhash
