#include "survey/survey_progress.hpp"

#include <cstdio>

namespace spinhash::survey {

std::string rate_text(double r) {
  char b[48];
  if (r >= 1e6)
    std::snprintf(b, sizeof b, "%.2f M points/s", r / 1e6);
  else if (r >= 1e3)
    std::snprintf(b, sizeof b, "%.1f k points/s", r / 1e3);
  else
    std::snprintf(b, sizeof b, "%.0f points/s", r);
  return b;
}

SurveyProgress::SurveyProgress(uint32_t total, uint32_t kept, uint32_t refused, bool quiet)
    : total_(total),
      done_(kept + refused),
      already_(kept + refused),
      kept_(kept),
      refused_(refused),
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
  std::string counted;
  if (kept_ > 0) counted += std::to_string(kept_) + " kept";
  if (refused_ > 0) counted += (counted.empty() ? "" : ", ") + std::to_string(refused_) + " refused";
  std::fprintf(stderr, "[survey] %u/%u tiles%s, %s, %.1f s, ETA %.0f s\n", done_, total_,
               counted.empty() ? "" : (" (" + counted + ")").c_str(),
               rate_text(secs > 0 ? static_cast<double>(points_) / secs : 0.0).c_str(), secs, eta);
}

}  // namespace spinhash::survey
