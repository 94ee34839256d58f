// The JSON writer of the command's lines lives in pipeline/json_line.hpp
// (the survey writes the same lines); the commands use it under cli::.
#pragma once
#include "pipeline/json_line.hpp"

namespace spinhash::cli {

using pipeline::json_array;
using pipeline::json_member;
using pipeline::json_number;
using pipeline::json_object;
using pipeline::json_string;
using pipeline::json_version_member;

}  // namespace spinhash::cli
