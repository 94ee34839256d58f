// The survey's progress line on stderr: tiles done of all the survey's
// tiles (those refused at their header and those a resumed run kept count
// as done, and are said), points per second in units that show the rate
// (points/s, k or M points/s) and the time left, at most every
// kSurveyProgressInterval and once at the end. Safe to call from every
// job's thread.
#pragma once
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace spinhash::survey {

constexpr std::chrono::milliseconds kSurveyProgressInterval(2000);

// "1.23 M points/s", "45.6 k points/s", "812 points/s".
std::string rate_text(double points_per_second);

class SurveyProgress {
 public:
  // total: every tile of the survey; kept: done by an earlier run
  // (--resume); refused: refused at their header. Both count as done.
  SurveyProgress(uint32_t total, uint32_t kept, uint32_t refused, bool quiet);
  void tile_done(uint64_t points);

 private:
  std::mutex mutex_;
  uint32_t total_, done_, already_, kept_, refused_;
  uint64_t points_ = 0;
  bool quiet_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace spinhash::survey
