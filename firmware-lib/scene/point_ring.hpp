// The stream's buffer: points of the stream frame (s, t, z) as 32-bit
// steps of the 1 mm lattice (window_lattice.hpp; 12 B a point), in arrival
// order, awaiting the windows and terrain cells that need them. Compacted
// after each row of windows, so it holds only what later rows still need;
// capacity fixed.
#pragma once
#include <cstdint>

#include "scene/window_lattice.hpp"
#include "spinhash/arena.hpp"

namespace spinhash {

struct PointRing {
  int32_t* steps = nullptr;  // 3 x capacity
  uint32_t capacity = 0;
  uint32_t count = 0;

  void carve(Arena& arena, uint32_t points) {
    capacity = points;
    steps = arena.alloc<int32_t>(3u * static_cast<size_t>(points));
  }
  // p: a frame point within_lattice.
  bool push(const double* p) {
    if (count >= capacity) return false;
    for (int a = 0; a < 3; ++a) steps[3u * static_cast<size_t>(count) + a] = lattice_steps(p[a]);
    ++count;
    return true;
  }
  void get(uint32_t i, double* out) const {
    for (int a = 0; a < 3; ++a) out[a] = from_steps(steps[3u * static_cast<size_t>(i) + a]);
  }
  // Keeps the points keep(k) accepts (k: the point's x y z steps), in order.
  template <class Keep>
  void keep_if_steps(Keep&& keep) {
    uint32_t kept = 0;
    for (uint32_t i = 0; i < count; ++i) {
      if (!keep(steps + 3u * static_cast<size_t>(i))) continue;
      if (kept != i)
        for (int a = 0; a < 3; ++a)
          steps[3u * static_cast<size_t>(kept) + a] = steps[3u * static_cast<size_t>(i) + a];
      ++kept;
    }
    count = kept;
  }
};

}  // namespace spinhash
