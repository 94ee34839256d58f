#include "scene/segment.hpp"

#include <cmath>

#include "geometry/xy_frame.hpp"
#include "util/union_find.hpp"

namespace spinhash {
namespace {

constexpr uint32_t kLayers = 2;  // low (vehicles, walls, trunks) and high (crowns, roofs)

uint32_t coord(float v, float v0, float cell, uint32_t count) {
  const float c = (v - v0) / cell;
  if (!(c > 0.0f)) return 0;
  const uint32_t i = static_cast<uint32_t>(c);
  return i < count ? i : count - 1u;
}

// The cell of a point above ground: its cell of the whole footprint, less
// the grid's offset (the points above ground lie within [ox, ox + nx)).
uint32_t cell_of(const SegmentGrid& g, const float* p) {
  return (coord(p[1], g.y0, g.cell, g.frame_ny) - g.oy) * g.nx +
         (coord(p[0], g.x0, g.cell, g.frame_nx) - g.ox);
}

uint32_t height_bin(float h, float bin) {
  const float b = h / bin;
  if (!(b > 0.0f)) return 0;
  return b < static_cast<float>(kSegmentColumnBins - 1u) ? static_cast<uint32_t>(b) : kSegmentColumnBins - 1u;
}

// Turns each cell's occupied-bin mask into its low layer's bins: the lowest
// occupied bin (low byte) and the highest reached from it without
// gap_bins empty bins on the way (second byte).
void column_tops(SegmentGrid& g, uint32_t gap_bins) {
  const uint32_t cells = g.nx * g.ny;
  for (uint32_t c = 0; c < cells; ++c) {
    const uint32_t mask = g.column[c];
    uint32_t low = 0, top = 0, empty = 0;
    bool started = false;
    for (uint32_t b = 0; b < kSegmentColumnBins; ++b) {
      if (mask & (1u << b)) {
        if (started && empty >= gap_bins) break;
        if (!started) low = b;
        started = true;
        top = b;
        empty = 0;
      } else {
        ++empty;
      }
    }
    g.column[c] = low | top << 8;
  }
}

// Slot of a non-ground point: layer * cells + cell. High: above split, or
// above a gap in its cell's column.
uint32_t slot_of(const SegmentGrid& g, const float* p, float h, const SegmentParams& params) {
  const uint32_t cells = g.nx * g.ny;
  const uint32_t c = cell_of(g, p);
  return (h > params.split_height || height_bin(h, params.column_bin) > (g.column[c] >> 8) ? cells : 0u) + c;
}

// Low-layer cells join only when their columns overlap in height (within a
// bin): the low fringe of a crown beside a car does not join the car.
bool columns_touch(const SegmentGrid& g, uint32_t a, uint32_t b) {
  const uint32_t lo_a = g.column[a] & 0xFFu, hi_a = g.column[a] >> 8;
  const uint32_t lo_b = g.column[b] & 0xFFu, hi_b = g.column[b] >> 8;
  return lo_a <= hi_b + 1u && lo_b <= hi_a + 1u;
}

void link_neighbours(SegmentGrid& g) {
  const uint32_t cells = g.nx * g.ny;
  // Half of the 8-neighbourhood (E, NW, N, NE) visits every adjacent pair once.
  const int dx[4] = {1, -1, 0, 1};
  const int dy[4] = {0, 1, 1, 1};
  for (uint32_t layer = 0; layer < kLayers; ++layer) {
    const uint32_t base = layer * cells;  // parents hold slots of the whole array
    uint32_t* parent = g.parent;
    for (uint32_t y = 0; y < g.ny; ++y)
      for (uint32_t x = 0; x < g.nx; ++x) {
        const uint32_t c = base + y * g.nx + x;
        if (parent[c] == kNoObject) continue;
        for (int k = 0; k < 4; ++k) {
          const int nx = static_cast<int>(x) + dx[k], ny = static_cast<int>(y) + dy[k];
          if (nx < 0 || nx >= static_cast<int>(g.nx) || ny >= static_cast<int>(g.ny)) continue;
          const uint32_t d = base + static_cast<uint32_t>(ny) * g.nx + static_cast<uint32_t>(nx);
          if (parent[d] == kNoObject) continue;
          if (layer == 0 && !columns_touch(g, c, d)) continue;
          unite(parent, c, d);
        }
      }
  }
}

void start_shape(ObjectShape& o, bool high) {
  o = ObjectShape{};
  o.high_layer = high;
  o.zmin = o.hmin = INFINITY;
  o.zmax = o.hmax = -INFINITY;
  o.umin = o.vmin = INFINITY;
  o.umax = o.vmax = -INFINITY;
}

// Principal axis of the footprint from the second moments.
void set_axes(ObjectShape& o) {
  const double n = static_cast<double>(o.points);
  const double mx = o.sx / n, my = o.sy / n;
  const double cxx = o.sxx / n - mx * mx, cyy = o.syy / n - my * my, cxy = o.sxy / n - mx * my;
  const double angle = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
  o.ax = static_cast<float>(std::cos(angle));
  o.ay = static_cast<float>(std::sin(angle));
}

// The frame over all n points (the footprint's min corner snapped to the
// cell: the objects' sums are taken from it) and the grid over the cells
// its points above ground span. false with nx = 0 when every point is
// ground; false with nx > 0 when the grid needs more than max_cells.
bool fit_frame(const float* xyz, const uint8_t* ground, uint32_t n, float cell, SegmentGrid& g) {
  g.nx = g.ny = 0;
  float lo[2], hi[2];
  xy_bounds(xyz, n, lo, hi);
  g.cell = cell;
  g.x0 = snap_down(lo[0], cell);
  g.y0 = snap_down(lo[1], cell);
  const float fx = (hi[0] - g.x0) / cell + 1.0f, fy = (hi[1] - g.y0) / cell + 1.0f;
  if (!(fx < 4.0e9f && fy < 4.0e9f)) {
    g.nx = 1;  // not empty: refused
    return false;
  }
  g.frame_nx = static_cast<uint32_t>(fx);
  g.frame_ny = static_cast<uint32_t>(fy);
  uint32_t c_lo[2] = {0xFFFFFFFFu, 0xFFFFFFFFu}, c_hi[2] = {0, 0};
  for (uint32_t i = 0; i < n; ++i) {
    if (ground[i]) continue;
    const uint32_t c[2] = {coord(xyz[3u * i], g.x0, cell, g.frame_nx),
                           coord(xyz[3u * i + 1u], g.y0, cell, g.frame_ny)};
    for (int a = 0; a < 2; ++a) {
      c_lo[a] = c[a] < c_lo[a] ? c[a] : c_lo[a];
      c_hi[a] = c[a] > c_hi[a] ? c[a] : c_hi[a];
    }
  }
  if (c_lo[0] > c_hi[0]) return false;  // all ground
  g.ox = c_lo[0];
  g.oy = c_lo[1];
  g.nx = c_hi[0] - c_lo[0] + 1u;
  g.ny = c_hi[1] - c_lo[1] + 1u;
  return static_cast<uint64_t>(g.nx) * g.ny <= g.max_cells;
}

}  // namespace

void SegmentGrid::carve(Arena& arena, uint32_t cells) {
  max_cells = cells;
  parent = arena.alloc<uint32_t>(static_cast<size_t>(kLayers) * cells);
  object = arena.alloc<uint32_t>(static_cast<size_t>(kLayers) * cells);
  column = arena.alloc<uint32_t>(cells);
}

Status segment_objects(const float* xyz, const float* height, const uint8_t* ground, uint32_t n,
                       const SegmentParams& params, SegmentGrid& g, ObjectShape* objects, uint32_t* label,
                       SegmentStats* stats) {
  SegmentStats st;
  if (n == 0) {
    if (stats) *stats = st;
    return Status::kOk;
  }
  if (!fit_frame(xyz, ground, n, params.cell, g)) {
    for (uint32_t i = 0; i < n; ++i) label[i] = kNoObject;
    if (stats) *stats = st;
    return g.nx == 0 ? Status::kOk : Status::kTileTooLarge;  // all ground, or too wide
  }
  const uint32_t cells = g.nx * g.ny;
  st.cells = cells;
  for (uint32_t s = 0; s < kLayers * cells; ++s) {
    g.parent[s] = kNoObject;
    g.object[s] = 0;
  }
  for (uint32_t c = 0; c < cells; ++c) g.column[c] = 0;
  for (uint32_t i = 0; i < n; ++i)
    if (!ground[i]) g.column[cell_of(g, xyz + 3u * i)] |= 1u << height_bin(height[i], params.column_bin);
  column_tops(g, params.layer_gap_bins);
  for (uint32_t i = 0; i < n; ++i)
    if (!ground[i]) {
      const uint32_t s = slot_of(g, xyz + 3u * i, height[i], params);
      g.parent[s] = s;
    }
  link_neighbours(g);
  for (uint32_t i = 0; i < n; ++i)
    if (!ground[i]) ++g.object[find_root(g.parent, slot_of(g, xyz + 3u * i, height[i], params))];
  // Object ids in slot order: deterministic, independent of the point order.
  for (uint32_t s = 0; s < kLayers * cells; ++s) {
    if (g.parent[s] != s) continue;
    ++st.components;
    const uint32_t count = g.object[s];
    if (count < params.min_points) {
      g.object[s] = kNoObject;
    } else if (st.objects >= params.max_objects) {
      ++st.dropped;
      g.object[s] = kNoObject;
    } else {
      start_shape(objects[st.objects], s >= cells);
      g.object[s] = st.objects++;
    }
  }
  for (uint32_t i = 0; i < n; ++i) {
    label[i] = kNoObject;
    if (ground[i]) continue;
    const uint32_t id = g.object[find_root(g.parent, slot_of(g, xyz + 3u * i, height[i], params))];
    if (id == kNoObject) continue;
    label[i] = id;
    ObjectShape& o = objects[id];
    const float* p = xyz + 3u * i;
    const double x = static_cast<double>(p[0] - g.x0), y = static_cast<double>(p[1] - g.y0);
    ++o.points;
    o.sx += x;
    o.sy += y;
    o.sxx += x * x;
    o.sxy += x * y;
    o.syy += y * y;
    o.zmin = p[2] < o.zmin ? p[2] : o.zmin;
    o.zmax = p[2] > o.zmax ? p[2] : o.zmax;
    o.hmin = height[i] < o.hmin ? height[i] : o.hmin;
    o.hmax = height[i] > o.hmax ? height[i] : o.hmax;
  }
  for (uint32_t k = 0; k < st.objects; ++k) set_axes(objects[k]);
  for (uint32_t i = 0; i < n; ++i) {
    if (label[i] == kNoObject) continue;
    ObjectShape& o = objects[label[i]];
    const float x = xyz[3u * i] - g.x0, y = xyz[3u * i + 1u] - g.y0;
    const float u = o.ax * x + o.ay * y, v = -o.ay * x + o.ax * y;
    o.umin = u < o.umin ? u : o.umin;
    o.umax = u > o.umax ? u : o.umax;
    o.vmin = v < o.vmin ? v : o.vmin;
    o.vmax = v > o.vmax ? v : o.vmax;
  }
  for (uint32_t k = 0; k < st.objects; ++k) {
    ObjectShape& o = objects[k];
    const float uc = 0.5f * (o.umin + o.umax), vc = 0.5f * (o.vmin + o.vmax);
    o.cx = g.x0 + o.ax * uc - o.ay * vc;
    o.cy = g.y0 + o.ay * uc + o.ax * vc;
  }
  if (stats) *stats = st;
  return st.dropped > 0 ? Status::kTooManyObjects : Status::kOk;
}

}  // namespace spinhash
