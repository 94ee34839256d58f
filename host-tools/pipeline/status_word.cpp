#include "pipeline/status_word.hpp"

namespace spinhash::pipeline {

const char* status_word(Status s) {
  switch (s) {
#define SPINHASH_STATUS_WORD(cxx, value, c, word, message) \
  case Status::cxx: return word;
    SPINHASH_STATUS_LIST(SPINHASH_STATUS_WORD)
#undef SPINHASH_STATUS_WORD
  }
  return "error";
}

}  // namespace spinhash::pipeline
