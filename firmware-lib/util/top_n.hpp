// The n best of `count` indexed items, best first, by insertion into a short
// sorted list: O(count * n) comparisons, no allocation, fully determined for
// a strict order (callers break ties by index).
#pragma once
#include <cstdint>

namespace spinhash {

// Writes to out[0, n) the indices i < count with keep(i), ordered so that
// better(out[j], out[j + 1]); returns how many were written (<= n).
template <typename Keep, typename Better>
uint32_t top_n(uint32_t count, uint32_t n, uint32_t* out, Keep keep, Better better) {
  uint32_t filled = 0;
  for (uint32_t item = 0; item < count; ++item) {
    if (!keep(item)) continue;
    uint32_t i = filled < n ? filled++ : n;
    while (i > 0 && better(item, out[i - 1u])) {
      if (i < n) out[i] = out[i - 1u];
      --i;
    }
    if (i < n) out[i] = item;
  }
  return filled;
}

}  // namespace spinhash
