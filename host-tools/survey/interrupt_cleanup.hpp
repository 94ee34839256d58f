// A survey interrupted by SIGINT (Ctrl-C) or SIGTERM (a scheduler's kill)
// removes its spill folders (pipeline/spill_folder.hpp), says what it kept
// (the tiles' results stored so far: --resume takes them) and exits with
// 128 + the signal's number. A thread of its own waits for the signals
// (sigwait), so the cleanup runs as ordinary code, not in a handler.
// Construct it before any worker thread: they inherit the blocked signals.
#pragma once

#include <pthread.h>

#include <string>
#include <thread>

namespace spinhash::survey {

class InterruptCleanup {
 public:
  explicit InterruptCleanup(std::string command);
  ~InterruptCleanup();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

 private:
  std::string command_;
  sigset_t previous_;
  std::thread watcher_;
};

}  // namespace spinhash::survey
