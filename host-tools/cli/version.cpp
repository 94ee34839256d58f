#include "cli/version.hpp"

namespace spinhash::cli {
const char* version() { return "0.1.0"; }
}  // namespace spinhash::cli
