// Whole-file writes that never leave a half-written file at the target path:
// the bytes go to PATH.tmp, which is renamed over PATH only when complete.
#pragma once

#include <string>

namespace spinhash::host {

bool write_file_atomically(const std::string& path, const std::string& bytes,
                           std::string* error);

}  // namespace spinhash::host
