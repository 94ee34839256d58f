// A recognizer configuration as one line of text, every field of the field
// lists by its key ("mode bran; seed 1; ...; ground.enabled on; ..."): the
// experiments' summaries and the survey's settings key.
#pragma once
#include <string>

#include "spinhash/config.hpp"

namespace spinhash::host {

// `with_mode` false: every field but the mode (the experiments list their modes).
std::string config_text(const RecognizerConfig& c, bool with_mode = true);

}  // namespace spinhash::host
