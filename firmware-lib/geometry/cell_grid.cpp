#include "geometry/cell_grid.hpp"

#include "util/fibonacci_hash.hpp"

namespace spinhash {

bool CellGrid::carve(Arena& arena, uint32_t max_points) {
  max_points_ = max_points;
  max_capacity_ = next_pow2(2u * (max_points > 0 ? max_points : 1u));
  capacity_ = max_capacity_;
  slot_shift_ = slot_shift(capacity_);
  keys_ = arena.alloc<uint64_t>(max_capacity_);
  first_ = arena.alloc<uint32_t>(max_capacity_);
  count_ = arena.alloc<uint32_t>(max_capacity_);
  slots_in_order_ = arena.alloc<uint32_t>(max_points);
  order_ = arena.alloc<uint32_t>(max_points);
  point_slot_ = arena.alloc<uint32_t>(max_points);
  cell_count_ = 0;
  if (arena.overflowed()) return false;
  // Every slot free once; each build then frees only the cells of the last.
  for (uint32_t s = 0; s < max_capacity_; ++s) keys_[s] = kEmptyCellKey;
  return true;
}

uint32_t CellGrid::insert(uint64_t key) {
  uint32_t slot = home_slot(key);
  // Load <= 1/2, so a free slot is always found within capacity_ probes.
  for (uint32_t probe = 0; probe < capacity_; ++probe) {
    if (keys_[slot] == key) return slot;
    if (keys_[slot] == kEmptyCellKey) {
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
  // The last build's cells are the only slots in use (carve freed them all):
  // freeing them costs a store per cell, not one per slot of the table.
  for (uint32_t c = 0; c < cell_count_; ++c) keys_[slots_in_order_[c]] = kEmptyCellKey;
  cell_count_ = 0;
  if (n > max_points_) n = max_points_;
  // A table sized for these n points (load <= 1/2), not for max_points. The
  // cells keep the order they were first seen in whatever the table's size,
  // so every pass over them is the same.
  capacity_ = next_pow2(2u * (n > 0 ? n : 1u));
  if (capacity_ > max_capacity_) capacity_ = max_capacity_;
  slot_shift_ = slot_shift(capacity_);
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

bool CellGrid::slab_gaps(const float* q, float radius, int32_t reach,
                         float (*gap)[2 * kMaxCulledReach + 1]) const {
  if (reach > kMaxCulledReach) return false;
  const int32_t rim = kCoordBias - 2;
  for (int a = 0; a < 3; ++a) {
    const float v = q[a];
    const int32_t centre = coord(v);
    // Each slab [c, c + 1) * cell_ widened by the slack; 0 inside, and 0 at
    // the clamped rim (coord), whose cells also hold the points beyond it.
    const float slack = kCullSlack * (std::fabs(v) + radius);
    for (int32_t d = -reach; d <= reach; ++d) {
      const int32_t c = centre + d;
      const float lo = static_cast<float>(c) * cell_ - slack;
      const float hi = static_cast<float>(c + 1) * cell_ + slack;
      const float g = c <= -rim || c >= rim ? 0.0f : (v < lo ? lo - v : (v > hi ? v - hi : 0.0f));
      gap[a][d + reach] = g * g;
    }
  }
  return true;
}

uint32_t CellGrid::gather_neighbourhood(uint32_t i, int32_t reach, float* x, float* y, float* z,
                                        uint32_t capacity) const {
  uint32_t count = 0;
  const float* points = points_;
  for_each_cell_near(i, reach, [&](const uint32_t* it, uint32_t size) {
    if (size > capacity - count) {
      count = kGatherOverflow;
      return false;
    }
    // Locals, so the stores need not reload the cell's count and start.
    float *cx = x + count, *cy = y + count, *cz = z + count;
    for (uint32_t k = 0; k < size; ++k) {
      const float* p = points + 3u * it[k];
      cx[k] = p[0];
      cy[k] = p[1];
      cz[k] = p[2];
    }
    count += size;
    return true;
  });
  return count;
}

}  // namespace spinhash
