#include "spinhash/status.hpp"

namespace spinhash {

const char* status_name(Status s) noexcept {
  switch (s) {
#define SPINHASH_STATUS_MESSAGE(cxx, value, c, word, message) \
  case Status::cxx: return message;
    SPINHASH_STATUS_LIST(SPINHASH_STATUS_MESSAGE)
#undef SPINHASH_STATUS_MESSAGE
  }
  return "unknown";
}

}  // namespace spinhash
