#include <algorithm>

#include "cli/commands.hpp"
#include "cloud/cloud_reader.hpp"

namespace spinhash::cli {

void refuse_repeated_stdin(const std::vector<std::string>& clouds) {
  if (std::count(clouds.begin(), clouds.end(), host::kStdinPath) > 1)
    throw CLI::ValidationError("clouds", "'-' (stdin) named more than once: stdin can be read only once");
}

}  // namespace spinhash::cli
