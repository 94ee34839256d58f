// The core's single diagnostics channel (onboard rule 12, docs/onboard-rules.md): one process-wide
// hook set through spinhash_set_log_hook() (spinhash.h). Messages are string
// literals or short concatenations; with SPINHASH_NO_LOG_STRINGS they are
// compiled out and the hook receives "" with the level only.
#pragma once

namespace spinhash {

enum class LogLevel : int { kError = 1, kWarning = 2, kInfo = 3 };  // = SPINHASH_LOG_*

#ifdef SPINHASH_NO_LOG_STRINGS
#define SPINHASH_LOG_TEXT(literal) ""
#else
#define SPINHASH_LOG_TEXT(literal) literal
#endif

// Calls the hook, if one is set, with prefix followed by detail (either may be
// null). Joins in a bounded stack buffer; longer messages are cut.
void log_message(LogLevel level, const char* prefix, const char* detail = nullptr) noexcept;

}  // namespace spinhash
