// Whether a recognition's status comes with an answer: kOk, or
// kWorkCapReached (the work cap stopped the search; its ranking is the best
// found so far, never confident). Every consumer of a Result asks this one
// question, not status == kOk.
#pragma once
#include "spinhash/status.hpp"

namespace spinhash {

inline bool has_answer(Status s) { return s == Status::kOk || s == Status::kWorkCapReached; }

}  // namespace spinhash
