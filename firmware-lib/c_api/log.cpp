#include "c_api/log.hpp"

#include "spinhash/spinhash.h"

namespace spinhash {
namespace {

constexpr unsigned kMaxLogMessageBytes = 96;  // including the NUL; small enough for any task stack
spinhash_log_hook g_log_hook = nullptr;       // set once at start-up by the firmware

unsigned append(char* out, unsigned used, const char* text) {
  for (; text != nullptr && *text != '\0' && used + 1u < kMaxLogMessageBytes; ++text) out[used++] = *text;
  return used;
}

}  // namespace

void log_message(LogLevel level, const char* prefix, const char* detail) noexcept {
  spinhash_log_hook hook = g_log_hook;
  if (hook == nullptr) return;
  char message[kMaxLogMessageBytes];
  unsigned used = append(message, 0u, prefix);
#ifndef SPINHASH_NO_LOG_STRINGS
  used = append(message, used, detail);
#else
  (void)detail;
#endif
  message[used] = '\0';
  hook(static_cast<int>(level), message);
}

}  // namespace spinhash

extern "C" void spinhash_set_log_hook(spinhash_log_hook hook) SPINHASH_NOEXCEPT {
  spinhash::g_log_hook = hook;
}
