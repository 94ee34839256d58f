// Minimal JSON output for the JSON Lines of `recognize` and friends.
#pragma once
#include <initializer_list>
#include <string>
#include <vector>

namespace spinhash::pipeline {

// Quoted and escaped. Text that is not valid UTF-8 (file names are bytes on
// POSIX) gets U+FFFD for each byte that does not start a valid sequence, so
// every line stays valid JSON.
std::string json_string(const std::string& s);
std::string json_number(double v, int digits = 9);  // null for NaN / infinity
// `"key":raw_value` and `{m1,m2,...}`: raw values are already JSON.
std::string json_member(const char* key, const std::string& raw_value);
std::string json_object(std::initializer_list<std::string> members);
std::string json_array(const std::vector<std::string>& raw_values);
// `"version":"X.Y.Z"` (pipeline/version.hpp): the last member of every JSON line.
std::string json_version_member();
// The line of a file that cannot be read, the same for `recognize` (key
// "query") and `scene` (key "tile"), so that readers pair lines with files:
// {KEY:NAME,"status":"unreadable","error":WHY,"ranking":[],"pose":null,"version":..}.
std::string unreadable_json(const char* key, const std::string& name, const std::string& error);

}  // namespace spinhash::pipeline
