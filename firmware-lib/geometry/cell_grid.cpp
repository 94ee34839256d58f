#include "geometry/cell_grid.hpp"

#include "spinhash/blob_format.hpp"
#include "util/fixed_math.hpp"

namespace spinhash {
namespace {
constexpr uint64_t kEmptyKey = ~0ull;
}

bool CellGrid::carve(Arena& arena, uint32_t max_points) {
  max_points_ = max_points;
  capacity_ = next_pow2(2u * (max_points > 0 ? max_points : 1u));
  keys_ = arena.alloc<uint64_t>(capacity_);
  first_ = arena.alloc<uint32_t>(capacity_);
  count_ = arena.alloc<uint32_t>(capacity_);
  slots_in_order_ = arena.alloc<uint32_t>(max_points);
  order_ = arena.alloc<uint32_t>(max_points);
  point_slot_ = arena.alloc<uint32_t>(max_points);
  return !arena.overflowed();
}

int32_t CellGrid::coord(float v) const {
  float c = std::floor(v / cell_);
  // Clouds wider than 2^20 cells are clamped at the rim (recentred input never is).
  const float lim = static_cast<float>(kCoordBias - 2);
  if (!(c > -lim)) c = -lim;  // also NaN: never convert a non-finite float to int
  if (!(c < lim)) c = lim;
  return static_cast<int32_t>(c);
}

uint64_t CellGrid::pack(int32_t x, int32_t y, int32_t z) {
  const uint64_t mask = (1ull << 21) - 1ull;
  return (static_cast<uint64_t>(x + kCoordBias) & mask) |
         ((static_cast<uint64_t>(y + kCoordBias) & mask) << 21) |
         ((static_cast<uint64_t>(z + kCoordBias) & mask) << 42);
}

int32_t CellGrid::find(uint64_t key) const {
  uint32_t slot = static_cast<uint32_t>(blob::mix64(key)) & (capacity_ - 1u);
  for (uint32_t probe = 0; probe < capacity_; ++probe) {
    if (keys_[slot] == key) return static_cast<int32_t>(slot);
    if (keys_[slot] == kEmptyKey) return -1;
    slot = (slot + 1u) & (capacity_ - 1u);
  }
  return -1;
}

uint32_t CellGrid::insert(uint64_t key) {
  uint32_t slot = static_cast<uint32_t>(blob::mix64(key)) & (capacity_ - 1u);
  // Load <= 1/2, so a free slot is always found within capacity_ probes.
  for (uint32_t probe = 0; probe < capacity_; ++probe) {
    if (keys_[slot] == key) return slot;
    if (keys_[slot] == kEmptyKey) {
      keys_[slot] = key;
      count_[slot] = 0;
      slots_in_order_[cell_count_++] = slot;
      return slot;
    }
    slot = (slot + 1u) & (capacity_ - 1u);
  }
  return slot;  // unreachable with load <= 1/2
}

void CellGrid::build(const float* points, uint32_t n, float cell) {
  points_ = points;
  cell_ = cell;
  cell_count_ = 0;
  if (n > max_points_) n = max_points_;
  for (uint32_t s = 0; s < capacity_; ++s) keys_[s] = kEmptyKey;
  for (uint32_t i = 0; i < n; ++i) {
    const float* p = points + 3u * i;
    uint32_t slot = insert(pack(coord(p[0]), coord(p[1]), coord(p[2])));
    point_slot_[i] = slot;
    ++count_[slot];
  }
  uint32_t start = 0;
  for (uint32_t c = 0; c < cell_count_; ++c) {
    uint32_t slot = slots_in_order_[c];
    first_[slot] = start;
    start += count_[slot];
    count_[slot] = 0;  // refilled below as a cursor
  }
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t slot = point_slot_[i];
    order_[first_[slot] + count_[slot]++] = i;
  }
}

}  // namespace spinhash
