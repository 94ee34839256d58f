// Status codes returned by every fallible core call. The enumerators, their
// values, messages, C names and JSON words are one list,
// SPINHASH_STATUS_LIST (status_list.h); values are part of the C ABI
// (spinhash.h): only ever append, never renumber.
#pragma once
#include <cstdint>

#include "spinhash/status_list.h"

namespace spinhash {

enum class Status : int32_t {
#define SPINHASH_STATUS_ENUMERATOR(cxx, value, c, word, message) cxx = value,
  SPINHASH_STATUS_LIST(SPINHASH_STATUS_ENUMERATOR)
#undef SPINHASH_STATUS_ENUMERATOR
};

// Short English name of a status (the list's message); "unknown" for values
// not listed.
const char* status_name(Status s) noexcept;

}  // namespace spinhash
