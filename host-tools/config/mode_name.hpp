// The recognizer's modes by name ("bran", "sran", "sind"): the CLI's --mode,
// Python's Config.mode and the experiments' tables use these names.
#pragma once
#include <map>
#include <string>

#include "spinhash/config.hpp"

namespace spinhash::host {

const std::map<std::string, Mode>& mode_names();
const char* mode_name(Mode m);  // "?" for a value out of range

}  // namespace spinhash::host
