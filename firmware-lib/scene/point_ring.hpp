// The stream's buffer: points in stream-frame doubles (s, t, z), in arrival
// order, awaiting the windows and terrain cells that need them. Compacted
// after each row of windows, so it holds only what later rows still need;
// capacity fixed.
#pragma once
#include <cstdint>

#include "spinhash/arena.hpp"

namespace spinhash {

struct PointRing {
  double* stz = nullptr;  // 3 x capacity
  uint32_t capacity = 0;
  uint32_t count = 0;

  void carve(Arena& arena, uint32_t points) {
    capacity = points;
    stz = arena.alloc<double>(3u * static_cast<size_t>(points));
  }
  bool push(const double* p) {
    if (count >= capacity) return false;
    for (int a = 0; a < 3; ++a) stz[3u * static_cast<size_t>(count) + a] = p[a];
    ++count;
    return true;
  }
  // Keeps the points keep(p) accepts, in order.
  template <class Keep>
  void keep_if(Keep&& keep) {
    uint32_t kept = 0;
    for (uint32_t i = 0; i < count; ++i) {
      const double* p = stz + 3u * static_cast<size_t>(i);
      if (!keep(p)) continue;
      if (kept != i)
        for (int a = 0; a < 3; ++a) stz[3u * static_cast<size_t>(kept) + a] = p[a];
      ++kept;
    }
    count = kept;
  }
};

}  // namespace spinhash
