// The project's version (CMake's PROJECT_VERSION), for --version and the
// "version" field of JSON output.
#pragma once

namespace spinhash::pipeline {

const char* version();

}  // namespace spinhash::pipeline
