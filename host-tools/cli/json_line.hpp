// Minimal JSON output for the JSON Lines of `recognize` and friends.
#pragma once
#include <string>

namespace spinhash::cli {

std::string json_string(const std::string& s);      // quoted and escaped
std::string json_number(double v, int digits = 9);  // null for NaN / infinity

}  // namespace spinhash::cli
