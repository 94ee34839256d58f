#include <algorithm>
#include <cstdio>

#include "cli/commands.hpp"
#include "cloud/cloud_reader.hpp"

namespace spinhash::cli {

void refuse_repeated_stdin(const std::vector<std::string>& clouds) {
  if (std::count(clouds.begin(), clouds.end(), host::kStdinPath) > 1)
    throw CLI::ValidationError("clouds", "'-' (stdin) named more than once: stdin can be read only once");
}

void print_error(const char* command, const std::string& message) {
  for (size_t start = 0; start <= message.size();) {
    size_t end = message.find('\n', start);
    if (end == std::string::npos) end = message.size();
    std::fprintf(stderr, "spinhash %s: %s\n", command, message.substr(start, end - start).c_str());
    start = end + 1;
  }
}

}  // namespace spinhash::cli
