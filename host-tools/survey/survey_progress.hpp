// The survey's progress line on stderr: tiles done of total, points per
// second and the time left, at most every kSurveyProgressInterval and once
// at the end. Safe to call from every job's thread.
#pragma once
#include <chrono>
#include <cstdint>
#include <mutex>

namespace spinhash::survey {

constexpr std::chrono::milliseconds kSurveyProgressInterval(2000);

class SurveyProgress {
 public:
  // already: tiles done by an earlier run (--resume), counted as done.
  SurveyProgress(uint32_t total, uint32_t already, bool quiet);
  void tile_done(uint64_t points);

 private:
  std::mutex mutex_;
  uint32_t total_, done_, already_;
  uint64_t points_ = 0;
  bool quiet_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace spinhash::survey
