// A violated invariant aborts, so libFuzzer records the input as a crash.
#pragma once
#include <cstdio>
#include <cstdlib>

namespace spinhash::fuzz {

inline void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz invariant violated: %s\n", what);
  std::abort();
}

}  // namespace spinhash::fuzz
