// Plain-text point clouds: "x y z" per line (space, tab or comma
// separated), extra columns ignored, '#' starts a comment, blank lines and
// one leading column-name line (e.g. "x y z") skipped.
#pragma once

#include <string>
#include <vector>

namespace spinhash::host {

bool read_text_cloud(const std::string& text, std::vector<double>* xyz, std::string* error);

}  // namespace spinhash::host
