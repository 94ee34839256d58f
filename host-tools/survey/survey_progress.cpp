#include "survey/survey_progress.hpp"

#include <cstdio>

namespace spinhash::survey {

SurveyProgress::SurveyProgress(uint32_t total, uint32_t already, bool quiet)
    : total_(total),
      done_(already),
      already_(already),
      quiet_(quiet),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void SurveyProgress::tile_done(uint64_t points) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  points_ += points;
  const auto now = std::chrono::steady_clock::now();
  if (quiet_ || (done_ < total_ && now - last_ < kSurveyProgressInterval)) return;
  last_ = now;
  const double secs = std::chrono::duration<double>(now - start_).count();
  const uint32_t run = done_ - already_;
  const double eta = run > 0 ? secs / run * (total_ - done_) : 0.0;
  std::fprintf(stderr, "[survey] %u/%u tiles, %.2f M points/s, %.1f s, ETA %.0f s\n", done_, total_,
               secs > 0 ? static_cast<double>(points_) / secs / 1e6 : 0.0, secs, eta);
}

}  // namespace spinhash::survey
