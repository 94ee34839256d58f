// Fixed-capacity voxel hash grid over a point array: points grouped by cell
// (counting sort through an open-addressing table), cells kept in the order
// they were first seen so every pass over them is deterministic.
#pragma once
#include <cmath>
#include <cstdint>

#include "spinhash/arena.hpp"
#include "util/fibonacci_hash.hpp"
#include "util/floor_int.hpp"

namespace spinhash {

class CellGrid {
 public:
  // Room for grids over up to max_points points (table load <= 1/2).
  bool carve(Arena& arena, uint32_t max_points);
  // Groups points[0, n) (xyz triples, n <= max_points) into cells of edge `cell`.
  void build(const float* points, uint32_t n, float cell);

  uint32_t cell_count() const { return cell_count_; }
  float cell_size() const { return cell_; }
  // i-th cell in first-seen order: its points are order()[first, first + count).
  uint32_t cell_first(uint32_t i) const { return first_[slots_in_order_[i]]; }
  uint32_t cell_size_of(uint32_t i) const { return count_[slots_in_order_[i]]; }
  const uint32_t* order() const { return order_; }

  // Calls f(point_index) for every point within `radius` of q (exact test),
  // cell by cell in z, y, x order. With kCull, cells whose box lies wholly
  // beyond the radius are skipped unvisited (a spin image's 5 x 5 x 5 cells
  // around a 1 m support: about a third of them): none of their points
  // would pass the test, so the points visited and their order are the same.
  template <bool kCull = true, typename F>
  void for_each_within(const float* q, float radius, F&& f) const {
    const int32_t reach = static_cast<int32_t>(std::ceil(radius / cell_));
    const int32_t cx = coord(q[0]), cy = coord(q[1]), cz = coord(q[2]);
    const float r2 = radius * radius;
    // Squared gap from q to each slab of cells, per axis (0 when q is in it).
    float gap[3][2 * kMaxCulledReach + 1];
    const bool cull = kCull && slab_gaps(q, radius, reach, gap);
    for (int32_t dz = -reach; dz <= reach; ++dz) {
      const float gz = cull ? gap[2][dz + reach] : 0.0f;
      if (gz > r2) continue;
      for (int32_t dy = -reach; dy <= reach; ++dy) {
        const float gyz = cull ? gz + gap[1][dy + reach] : 0.0f;
        if (gyz > r2) continue;
        for (int32_t dx = -reach; dx <= reach; ++dx) {
          if (cull && gyz + gap[0][dx + reach] > r2) continue;  // the whole cell is beyond the radius
          int32_t slot = find(pack(cx + dx, cy + dy, cz + dz));
          if (slot < 0) continue;
          const uint32_t* it = order_ + first_[slot];
          for (uint32_t k = 0; k < count_[slot]; ++k) {
            const float* p = points_ + 3u * it[k];
            float ex = p[0] - q[0], ey = p[1] - q[1], ez = p[2] - q[2];
            if (ex * ex + ey * ey + ez * ez <= r2) f(it[k]);
          }
        }
      }
    }
  }

  // Calls f(it, count) with the point indices of cell i (first-seen order)
  // and of every occupied cell within `reach` cells of it each way, cell by
  // cell in z, y, x order as for_each_within visits them from a point of
  // cell i; stops early when f returns false.
  template <typename F>
  void for_each_cell_near(uint32_t i, int32_t reach, F&& f) const {
    const uint64_t key = keys_[slots_in_order_[i]];
    const uint64_t mask = (1ull << 21) - 1ull;
    // The cell's coordinates back from its key (coord keeps them within 21 bits).
    const int32_t cx = static_cast<int32_t>(key & mask) - kCoordBias;
    const int32_t cy = static_cast<int32_t>((key >> 21) & mask) - kCoordBias;
    const int32_t cz = static_cast<int32_t>((key >> 42) & mask) - kCoordBias;
    for (int32_t dz = -reach; dz <= reach; ++dz)
      for (int32_t dy = -reach; dy <= reach; ++dy)
        for (int32_t dx = -reach; dx <= reach; ++dx) {
          const int32_t slot = find(pack(cx + dx, cy + dy, cz + dz));
          if (slot >= 0 && !f(order_ + first_[slot], count_[slot])) return;
        }
  }

  // The coordinates of the points for_each_cell_near visits into x[k],
  // y[k], z[k], k < capacity, in its order. Returns how many, or
  // kGatherOverflow when more than capacity (nothing usable).
  static constexpr uint32_t kGatherOverflow = 0xFFFFFFFFu;
  uint32_t gather_neighbourhood(uint32_t i, int32_t reach, float* x, float* y, float* z,
                                uint32_t capacity) const;
  // The reach of a search of `radius` (for_each_within's).
  int32_t reach_of(float radius) const { return static_cast<int32_t>(std::ceil(radius / cell_)); }

  // true when some point lies within `radius` of q (the same exact test as
  // for_each_within, over the cells the box [q - radius, q + radius] meets;
  // stops at the first).
  bool any_within(const float* q, float radius) const {
    const float r2 = radius * radius;
    const int32_t lo[3] = {coord(q[0] - radius), coord(q[1] - radius), coord(q[2] - radius)};
    const int32_t hi[3] = {coord(q[0] + radius), coord(q[1] + radius), coord(q[2] + radius)};
    for (int32_t z = lo[2]; z <= hi[2]; ++z)
      for (int32_t y = lo[1]; y <= hi[1]; ++y)
        for (int32_t x = lo[0]; x <= hi[0]; ++x) {
          const int32_t slot = find(pack(x, y, z));
          if (slot < 0) continue;
          const uint32_t* it = order_ + first_[slot];
          for (uint32_t k = 0; k < count_[slot]; ++k) {
            const float* p = points_ + 3u * it[k];
            const float ex = p[0] - q[0], ey = p[1] - q[1], ez = p[2] - q[2];
            if (ex * ex + ey * ey + ez * ez <= r2) return true;
          }
        }
    return false;
  }

 private:
  static constexpr int32_t kCoordBias = 1 << 20;  // 21-bit cell coordinates per axis
  // Radius searches reaching at most this many cells each way skip the
  // cells beyond the radius (the core's reach 1 or 2; wider ones visit all).
  static constexpr int32_t kMaxCulledReach = 4;
  // A cell's box is widened by this share of (|v| + radius) before its gap
  // is taken: far more than float rounding of the cell bounds, of
  // floor(v / cell) and of the points' squared distances, so a skipped cell
  // never holds a point that the exact test would pass.
  static constexpr float kCullSlack = 1.0e-4f;
  // The squared gaps from q to the slabs of cells within `reach` of its own,
  // per axis (gap[a][d + reach]); false when reach > kMaxCulledReach (no
  // culling).
  bool slab_gaps(const float* q, float radius, int32_t reach, float (*gap)[2 * kMaxCulledReach + 1]) const;
  static constexpr uint64_t kEmptyCellKey = ~0ull;
  // Inline: every radius search calls these for each of its 27 cells.
  inline int32_t coord(float v) const;
  static inline uint64_t pack(int32_t x, int32_t y, int32_t z);
  inline int32_t find(uint64_t key) const;
  inline uint32_t home_slot(uint64_t key) const;
  uint32_t insert(uint64_t key);

  uint64_t* keys_ = nullptr;   // per slot; kEmptyCellKey when free
  uint32_t* first_ = nullptr;  // per slot: start in order_
  uint32_t* count_ = nullptr;  // per slot: points in the cell
  uint32_t* slots_in_order_ = nullptr;
  uint32_t* order_ = nullptr;       // point indices grouped by cell
  uint32_t* point_slot_ = nullptr;  // slot of each point
  uint32_t capacity_ = 0;           // power of two: the table of the last build
  uint32_t max_capacity_ = 0;       // power of two: the table carved for max_points
  uint32_t slot_shift_ = 32;        // 32 - log2(capacity_)
  uint32_t max_points_ = 0;
  uint32_t cell_count_ = 0;
  float cell_ = 1.0f;
  const float* points_ = nullptr;
};

inline int32_t CellGrid::coord(float v) const {
  float t = v / cell_;
  // Clouds wider than 2^20 cells are clamped at the rim (recentred input
  // never is). lim is whole, so clamping before the floor gives the floor's
  // clamp.
  const float lim = static_cast<float>(kCoordBias - 2);
  if (!(t > -lim)) t = -lim;  // also NaN: never convert a non-finite float to int
  if (!(t < lim)) t = lim;
  return floor_to_int(t);
}

inline uint64_t CellGrid::pack(int32_t x, int32_t y, int32_t z) {
  const uint64_t mask = (1ull << 21) - 1ull;
  return (static_cast<uint64_t>(x + kCoordBias) & mask) |
         ((static_cast<uint64_t>(y + kCoordBias) & mask) << 21) |
         ((static_cast<uint64_t>(z + kCoordBias) & mask) << 42);
}

// Both halves of the key folded by 32-bit products into a Fibonacci hash
// (util/fibonacci_hash.hpp). Slots only place cells in the table: the cells'
// order is the order they were first seen.
inline uint32_t CellGrid::home_slot(uint64_t key) const {
  constexpr uint32_t kHighHalfMultiplier = 0x85EBCA77u;  // another odd constant (MurmurHash3's)
  const uint32_t h = static_cast<uint32_t>(key) * kFibonacciMultiplier ^
                     static_cast<uint32_t>(key >> 32) * kHighHalfMultiplier;
  return slot_of(h, slot_shift_);
}

inline int32_t CellGrid::find(uint64_t key) const {
  uint32_t slot = home_slot(key);
  for (uint32_t probe = 0; probe < capacity_; ++probe) {
    if (keys_[slot] == key) return static_cast<int32_t>(slot);
    if (keys_[slot] == kEmptyCellKey) return -1;
    slot = (slot + 1u) & (capacity_ - 1u);
  }
  return -1;
}

}  // namespace spinhash
