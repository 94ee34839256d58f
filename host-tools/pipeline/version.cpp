#include "pipeline/version.hpp"

namespace spinhash::pipeline {

const char* version() { return SPINHASH_VERSION; }  // defined by host-tools/CMakeLists.txt

}  // namespace spinhash::pipeline
