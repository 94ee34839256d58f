// Progress lines on stderr for work that takes more than a few seconds:
// at most one line every kProgressInterval, plus the last one.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace spinhash::pipeline {

class Progress {
 public:
  Progress(std::string stage, uint32_t total, bool quiet = false);
  void tick(uint32_t done);

 private:
  std::string stage_;
  uint32_t total_;
  bool quiet_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace spinhash::pipeline
