// Mode lists on the experiment command lines ("bran,sran,sind").
#pragma once
#include <string>
#include <vector>

#include "spinhash/config.hpp"

namespace spinhash::experiment {

bool parse_modes(const std::vector<std::string>& names, std::vector<Mode>* out, std::string* error);

}  // namespace spinhash::experiment
