#include "pipeline/progress.hpp"

#include <cstdio>

namespace spinhash::pipeline {
namespace {
constexpr std::chrono::milliseconds kProgressInterval(2000);
}

Progress::Progress(std::string stage, uint32_t total, bool quiet)
    : stage_(std::move(stage)),
      total_(total),
      quiet_(quiet),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void Progress::tick(uint32_t done) {
  auto now = std::chrono::steady_clock::now();
  if (quiet_ || (done < total_ && now - last_ < kProgressInterval)) return;
  last_ = now;
  double secs = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "[%s] %u/%u (%.1f s)\n", stage_.c_str(), done, total_, secs);
}

}  // namespace spinhash::pipeline
