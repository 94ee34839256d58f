// The stream's buffer: points of the stream frame (s, t, z) as 32-bit
// steps of the 1 mm lattice (window_lattice.hpp; 12 B a point), in arrival
// order, awaiting the windows and terrain cells that need them. Compacted
// after each row of windows, so it holds only what later rows still need;
// capacity fixed. Each block of kRingBlock points keeps the span of its s
// steps, so that a scan of an along-track range skips the blocks outside
// it (points come in along-track order, give or take the lag).
#pragma once
#include <cstdint>

#include "scene/window_lattice.hpp"
#include "spinhash/arena.hpp"

namespace spinhash {

constexpr uint32_t kRingBlock = 256;  // points per block: a span per 3 kB of steps

struct PointRing {
  int32_t* steps = nullptr;    // 3 x capacity
  int32_t* block_s = nullptr;  // per block: its least s step, then its largest
  uint32_t capacity = 0;
  uint32_t count = 0;

  void carve(Arena& arena, uint32_t points) {
    capacity = points;
    steps = arena.alloc<int32_t>(3u * static_cast<size_t>(points));
    block_s = arena.alloc<int32_t>(2u * (static_cast<size_t>(points) / kRingBlock + 1u));
  }
  // p: a frame point within_lattice.
  bool push(const double* p) {
    if (count >= capacity) return false;
    int32_t* k = steps + 3u * static_cast<size_t>(count);
    for (int a = 0; a < 3; ++a) k[a] = lattice_steps(p[a]);
    note(count, k[0]);
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
      note(kept, steps[3u * static_cast<size_t>(kept)]);
      ++kept;
    }
    count = kept;
  }
  // Calls f(i) for each point whose s step may lie in [s_lo, s_hi), in
  // order: every point of the blocks whose span meets the range (the
  // caller still tests each point).
  template <class F>
  void for_blocks_meeting(int64_t s_lo, int64_t s_hi, F&& f) const {
    for (uint32_t first = 0; first < count; first += kRingBlock) {
      const int32_t* span = block_s + 2u * (first / kRingBlock);
      if (span[1] < s_lo || span[0] >= s_hi) continue;
      const uint32_t end = count - first > kRingBlock ? first + kRingBlock : count;
      for (uint32_t i = first; i < end; ++i) f(i);
    }
  }

 private:
  // Point i (the last written) widens its block's span; the first of a block starts it.
  void note(uint32_t i, int32_t s) {
    int32_t* span = block_s + 2u * (i / kRingBlock);
    if (i % kRingBlock == 0) {
      span[0] = span[1] = s;
      return;
    }
    span[0] = s < span[0] ? s : span[0];
    span[1] = s > span[1] ? s : span[1];
  }
};

}  // namespace spinhash
