#include "scene/terrain_cells.hpp"

#include <cmath>

#include "util/floor_int.hpp"
#include "util/union_find.hpp"

namespace spinhash {

namespace {

constexpr uint16_t kNoBlock = 0xFFFFu;

uint32_t ceil_div(uint32_t a, uint32_t b) { return (a + b - 1u) / b; }

}  // namespace

void TerrainCells::carve(Arena& arena, double cell_m, double depth, double width) {
  cell = cell_m;
  along = static_cast<uint32_t>(std::ceil(depth / cell_m)) + 2u;
  across = static_cast<uint32_t>(std::ceil(width / cell_m)) + 2u;
  const size_t n = static_cast<size_t>(along) * across;
  lowest = arena.alloc<float>(n);
  next = arena.alloc<float>(n);
  band_sum = arena.alloc<float>(n);
  band_count = arena.alloc<float>(n);
  span = arena.alloc<uint32_t>(2u * static_cast<size_t>(along));
  block_box_ = arena.alloc<int32_t>(4u * kMaxTerrainBlocks);
  block_parent_ = arena.alloc<uint16_t>(kMaxTerrainBlocks);
  part_first_ = arena.alloc<int32_t>(2u * kMaxTerrainParts);
  cleared = false;  // new slots: cleared whole at the first start
}

void TerrainCells::start(double t_lo) {
  t_min = t_lo;
  started = false;
  if (lowest == nullptr || span == nullptr) return;
  for (uint32_t r = 0; r < along; ++r) {
    const uint32_t first = cleared ? span[2u * r] : 0u, last = cleared ? span[2u * r + 1u] : across - 1u;
    for (uint32_t it = first; it <= last && it < across; ++it) {
      const size_t c = static_cast<size_t>(r) * across + it;
      lowest[c] = NAN;
      next[c] = NAN;
      band_sum[c] = 0.0f;
      band_count[c] = 0.0f;
    }
    span[2u * r] = across;  // empty: first > last
    span[2u * r + 1u] = 0;
  }
  cleared = true;
}

int64_t TerrainCells::index_along(double s) const { return floor_to_int64(s / cell); }

uint32_t TerrainCells::slot(int64_t i, uint32_t it) const {
  const int64_t a = static_cast<int64_t>(along);
  const uint32_t row = static_cast<uint32_t>(((i % a) + a) % a);
  return row * across + it;
}

uint32_t* TerrainCells::span_of(int64_t i) const {
  const int64_t a = static_cast<int64_t>(along);
  return span + 2u * static_cast<uint32_t>(((i % a) + a) % a);
}

namespace {

// Calls f(row, it, z) for each ring point in cells [i0, i1) along and
// within the slots across (row: its slot row along), in the ring's
// (arrival) order.
template <class F>
void for_cell_points(const TerrainCells& tc, const PointRing& ring, int64_t i0, int64_t i1, F&& f) {
  const double s0 = static_cast<double>(i0) * tc.cell, s1 = static_cast<double>(i1) * tc.cell;
  const int64_t k0 = first_step_from(s0), k1 = first_step_from(s1);  // [s0, s1) on the steps
  const int64_t a = static_cast<int64_t>(tc.along);
  // Metres to cells: a product where the cell is a power of two (its
  // inverse exact, so the same correctly rounded quotient), else the division.
  int exponent = 0;
  const bool power_of_two = std::frexp(tc.cell, &exponent) == 0.5;
  const double inverse = power_of_two ? 1.0 / tc.cell : 0.0;
  auto in_cells = [&](double m) { return power_of_two ? m * inverse : m / tc.cell; };
  // Slot rows: i's is i0's plus i - i0 (i1 - i0 <= along), wrapped once;
  // the remainder where that is not enough (no division per point).
  const int64_t row0 = ((i0 % a) + a) % a;
  ring.for_blocks_meeting(k0, k1, [&](uint32_t k) {
    const int32_t* q = ring.steps + 3u * static_cast<size_t>(k);
    if (q[0] < k0 || q[0] >= k1) return;
    double p[3];
    ring.get(k, p);
    const int64_t t = floor_to_int64(in_cells(p[1] - tc.t_min));
    if (t < 0 || t >= static_cast<int64_t>(tc.across)) return;
    const int64_t i = floor_to_int64(in_cells(p[0]));  // index_along
    int64_t row = row0 + (i - i0);
    if (row >= a) row -= a;
    if (row < 0 || row >= a) row = ((i % a) + a) % a;
    f(static_cast<uint32_t>(row), static_cast<uint32_t>(t), static_cast<float>(p[2]));
  });
}

}  // namespace

void TerrainCells::sum(const PointRing& ring, double from_s, double to_s) {
  int64_t i0 = index_along(from_s);
  const int64_t i1 = index_along(to_s);
  if (started && summed_to > i0) i0 = summed_to;
  if (i1 - i0 > static_cast<int64_t>(along)) i0 = i1 - static_cast<int64_t>(along);  // older cells are gone
  for (int64_t i = i0; i < i1; ++i) {  // the slot row's cells of an older index, emptied
    uint32_t* sp = span_of(i);
    const uint32_t base = slot(i, 0);
    for (uint32_t it = sp[0]; it <= sp[1] && it < across; ++it) {
      const uint32_t c = base + it;
      lowest[c] = NAN;
      next[c] = NAN;
      band_sum[c] = 0.0f;
      band_count[c] = 0.0f;
    }
    sp[0] = across;
    sp[1] = 0;
  }
  for_cell_points(*this, ring, i0, i1, [&](uint32_t row, uint32_t it, float z) {
    const uint32_t c = row * across + it;
    terrain_lowest(lowest[c], next[c], z);
    uint32_t* sp = span + 2u * row;
    sp[0] = it < sp[0] ? it : sp[0];
    sp[1] = it > sp[1] ? it : sp[1];
  });
  for_cell_points(*this, ring, i0, i1, [&](uint32_t row, uint32_t it, float z) {
    const uint32_t c = row * across + it;
    terrain_low_band(terrain_band_base(lowest[c], next[c], noise_gap), z, low_band, band_sum[c],
                     band_count[c]);
  });
  if (!started || i1 > summed_to) summed_to = i1;
  started = true;
}

Status TerrainCells::fill(const FrameRect& rect, const FrameRect& needed, double s0, double t0,
                          uint32_t reach_cells, TerrainParts& parts) const {
  const int64_t i0 = index_along(rect.s0), i1 = index_along(rect.s1);
  const double t_lo = std::floor((rect.t0 - t_min) / cell), t_hi = std::ceil((rect.t1 - t_min) / cell);
  const uint32_t j0 = t_lo < 0.0 ? 0u : static_cast<uint32_t>(t_lo);
  const uint32_t j1 = t_hi > static_cast<double>(across) ? across : static_cast<uint32_t>(t_hi);
  if (i1 <= i0 || j1 <= j0 || i1 - i0 > static_cast<int64_t>(along)) return Status::kEmptyCloud;
  const uint32_t ni = static_cast<uint32_t>(i1 - i0), nj = j1 - j0;
  // Blocks of a kTerrainBlocksPerReach-th of the filter's reach (and a
  // cell's bilinear neighbours); coarser where the rectangle is wide.
  uint32_t b = ceil_div(reach_cells + 2u, kTerrainBlocksPerReach);
  const uint32_t b_fit = ceil_div(ni > nj ? ni : nj, kMaxTerrainBlockSide);
  b = b > b_fit ? b : b_fit;
  const uint32_t bi = ceil_div(ni, b), bj = ceil_div(nj, b);
  for (uint32_t k = 0; k < bi * bj; ++k) {
    block_parent_[k] = kNoBlock;
    block_box_[4u * k] = block_box_[4u * k + 2u] = 0x7FFFFFFF;
    block_box_[4u * k + 1u] = block_box_[4u * k + 3u] = -1;
  }
  // The footprint of each block's occupied cells (relative indices).
  bool any = false;
  for (int64_t i = i0; i < i1; ++i) {
    const uint32_t* sp = span_of(i);
    const uint32_t f = sp[0] > j0 ? sp[0] : j0, l = sp[1] + 1u < j1 ? sp[1] + 1u : j1;
    for (uint32_t j = f; j < l; ++j) {
      if (std::isnan(lowest[slot(i, j)])) continue;
      const int32_t ri = static_cast<int32_t>(i - i0), rj = static_cast<int32_t>(j - j0);
      const uint32_t k = (static_cast<uint32_t>(rj) / b) * bi + static_cast<uint32_t>(ri) / b;
      int32_t* box = block_box_ + 4u * k;
      box[0] = ri < box[0] ? ri : box[0];
      box[1] = ri > box[1] ? ri : box[1];
      box[2] = rj < box[2] ? rj : box[2];
      box[3] = rj > box[3] ? rj : box[3];
      block_parent_[k] = static_cast<uint16_t>(k);
      any = true;
    }
  }
  if (!any) return Status::kEmptyCloud;
  // Occupied blocks within kTerrainBlocksPerReach of each other (each pair
  // once: the half of the neighbourhood ahead) are one part.
  constexpr int32_t kReach = static_cast<int32_t>(kTerrainBlocksPerReach);
  for (uint32_t y = 0; y < bj; ++y)
    for (uint32_t x = 0; x < bi; ++x) {
      const uint32_t k = y * bi + x;
      if (block_parent_[k] == kNoBlock) continue;
      for (int32_t dy = 0; dy <= kReach; ++dy)
        for (int32_t dx = dy == 0 ? 1 : -kReach; dx <= kReach; ++dx) {
          const int32_t nx = static_cast<int32_t>(x) + dx, ny = static_cast<int32_t>(y) + dy;
          if (nx < 0 || nx >= static_cast<int32_t>(bi) || ny >= static_cast<int32_t>(bj)) continue;
          const uint32_t m = static_cast<uint32_t>(ny) * bi + static_cast<uint32_t>(nx);
          if (block_parent_[m] != kNoBlock)
            unite<uint16_t>(block_parent_, static_cast<uint16_t>(k), static_cast<uint16_t>(m));
        }
    }
  for (uint32_t k = 0; k < bi * bj; ++k) {  // each part's footprint into its root's box
    if (block_parent_[k] == kNoBlock) continue;
    const uint16_t r = find_root<uint16_t>(block_parent_, static_cast<uint16_t>(k));
    if (r == k) continue;
    int32_t *into = block_box_ + 4u * r, *box = block_box_ + 4u * k;
    into[0] = box[0] < into[0] ? box[0] : into[0];
    into[1] = box[1] > into[1] ? box[1] : into[1];
    into[2] = box[2] < into[2] ? box[2] : into[2];
    into[3] = box[3] > into[3] ? box[3] : into[3];
  }
  // The needed rectangle in relative cells (a part reaching into it is made).
  const double n_i0 = std::floor(needed.s0 / cell) - static_cast<double>(i0),
               n_i1 = std::floor(needed.s1 / cell) - static_cast<double>(i0);
  const double n_j0 = std::floor((needed.t0 - t_min) / cell) - static_cast<double>(j0),
               n_j1 = std::floor((needed.t1 - t_min) / cell) - static_cast<double>(j0);
  const float cell_f = static_cast<float>(cell);
  if (!terrain_parts_begin(parts, cell_f, static_cast<float>(static_cast<double>(i0) * cell - s0),
                           static_cast<float>(t_min + static_cast<double>(j0) * cell - t0), b, bi, bj))
    return Status::kTileTooLarge;
  for (uint32_t k = 0; k < bi * bj; ++k) {  // a part per root, in block order
    if (block_parent_[k] == kNoBlock || find_root<uint16_t>(block_parent_, static_cast<uint16_t>(k)) != k)
      continue;
    const int32_t* box = block_box_ + 4u * k;
    if (static_cast<double>(box[1]) < n_i0 || static_cast<double>(box[0]) > n_i1 ||
        static_cast<double>(box[3]) < n_j0 || static_cast<double>(box[2]) > n_j1)
      continue;  // wholly outside what is needed
    const int64_t lo_i = i0 + box[0];
    const uint32_t lo_j = j0 + static_cast<uint32_t>(box[2]);
    const uint8_t p = terrain_add_part(parts, static_cast<float>(static_cast<double>(lo_i) * cell - s0),
                                       static_cast<float>(t_min + static_cast<double>(lo_j) * cell - t0),
                                       static_cast<uint32_t>(box[1] - box[0] + 1),
                                       static_cast<uint32_t>(box[3] - box[2] + 1));
    if (p == kNoTerrainPart) return Status::kTileTooLarge;
    part_first_[2u * p] = box[0];
    part_first_[2u * p + 1u] = box[2];
    parts.block_part[k] = p;
  }
  if (parts.count == 0) return Status::kEmptyCloud;
  for (uint32_t k = 0; k < bi * bj; ++k)
    if (block_parent_[k] != kNoBlock)
      parts.block_part[k] = parts.block_part[find_root<uint16_t>(block_parent_, static_cast<uint16_t>(k))];
  for (int64_t i = i0; i < i1; ++i) {
    const uint32_t* sp = span_of(i);
    const uint32_t f = sp[0] > j0 ? sp[0] : j0, l = sp[1] + 1u < j1 ? sp[1] + 1u : j1;
    for (uint32_t j = f; j < l; ++j) {
      const uint32_t c = slot(i, j);
      if (std::isnan(lowest[c])) continue;
      const uint32_t ri = static_cast<uint32_t>(i - i0), rj = j - j0;
      const uint8_t p = parts.block_part[(rj / b) * bi + ri / b];
      if (p == kNoTerrainPart) continue;  // not needed
      terrain_put_cell(parts.part[p], ri - static_cast<uint32_t>(part_first_[2u * p]),
                       rj - static_cast<uint32_t>(part_first_[2u * p + 1u]), lowest[c], next[c], band_sum[c],
                       band_count[c]);
    }
  }
  return Status::kOk;
}

}  // namespace spinhash
