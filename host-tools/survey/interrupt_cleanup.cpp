#include "survey/interrupt_cleanup.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>

#include "pipeline/spill_folder.hpp"

namespace spinhash::survey {
namespace {

// SIGUSR2 only wakes the watcher when the survey ends normally.
sigset_t watched() {
  sigset_t s;
  sigemptyset(&s);
  sigaddset(&s, SIGINT);
  sigaddset(&s, SIGTERM);
  sigaddset(&s, SIGUSR2);
  return s;
}

}  // namespace

InterruptCleanup::InterruptCleanup(std::string command) : command_(std::move(command)) {
  const sigset_t s = watched();
  pthread_sigmask(SIG_BLOCK, &s, &previous_);
  watcher_ = std::thread([this] {
    const sigset_t w = watched();
    int sig = 0;
    if (sigwait(&w, &sig) != 0 || sig == SIGUSR2) return;
    const size_t removed = pipeline::remove_own_spill_folders();
    std::fprintf(
        stderr,
        "spinhash %s: interrupted (%s): removed %zu temporary folder%s; the tiles stored so far are kept "
        "(run again with --resume)\n",
        command_.c_str(), sig == SIGINT ? "SIGINT" : "SIGTERM", removed, removed == 1 ? "" : "s");
    std::fflush(stderr);
    ::_exit(128 + sig);
  });
}

InterruptCleanup::~InterruptCleanup() {
  pthread_kill(watcher_.native_handle(), SIGUSR2);
  watcher_.join();
  pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

}  // namespace spinhash::survey
