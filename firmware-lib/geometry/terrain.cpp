#include "geometry/terrain.hpp"

#include <cmath>

#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

bool no_data(float v) { return std::isnan(v); }

uint32_t cell_coord(float v, float v0, float cell, uint32_t count) {
  const float c = (v - v0) / cell;
  if (!(c > 0.0f)) return 0;
  const uint32_t i = static_cast<uint32_t>(c);
  return i < count ? i : count - 1u;
}

}  // namespace

// van Herk / Gil-Werman: blocks of k = 2r + 1 cells; per block the running
// extreme from its left end (into out) and from its right end (into line);
// a window of k cells spans at most two blocks, so each cell costs three
// comparisons whatever r (the direct scan costs 2r + 1). Min and max are
// exact: the same values as the direct scan. No data (NaN) enters as the
// extreme's identity and leaves as NaN.
void terrain_line_filter(const float* in, float* out, float* line, uint32_t nx, uint32_t ny, uint32_t r,
                         bool along_x, bool erode) {
  const uint32_t lines = along_x ? ny : nx;
  const uint32_t len = along_x ? nx : ny;
  const uint32_t step = along_x ? 1u : nx;
  const uint32_t k = 2u * r + 1u;
  const float identity = erode ? INFINITY : -INFINITY;
  auto pick = [erode](float a, float b) { return erode ? (b < a ? b : a) : (b > a ? b : a); };
  auto value = [identity](float v) { return no_data(v) ? identity : v; };
  for (uint32_t l = 0; l < lines; ++l) {
    const uint32_t base = along_x ? l * nx : l;
    uint32_t first = 0;  // a line without data stays without (sparse parts have many)
    while (first < len && no_data(in[base + first * step])) ++first;
    if (first == len) {
      for (uint32_t i = 0; i < len; ++i) out[base + i * step] = NAN;
      continue;
    }
    float run = identity;
    for (uint32_t i = 0; i < len; ++i) {
      const float v = value(in[base + i * step]);
      run = i % k == 0 ? v : pick(run, v);
      out[base + i * step] = run;  // from the block's start to i
    }
    for (uint32_t i = len; i-- > 0;) {
      const float v = value(in[base + i * step]);
      line[i] = (i % k == k - 1u || i == len - 1u) ? v : pick(line[i + 1u], v);  // from i to the block's end
    }
    for (uint32_t i = 0; i < len; ++i) {  // out[j] for j >= i still holds the running extreme
      const uint32_t lo = i > r ? i - r : 0u;
      const uint32_t hi = i + r < len ? i + r : len - 1u;
      float m;
      if (lo / k != hi / k)
        m = pick(line[lo], out[base + hi * step]);
      else
        m = lo % k == 0 ? out[base + hi * step] : line[lo];  // a truncated window within one block
      out[base + i * step] = m == identity ? NAN : m;
    }
  }
}

namespace {

// g.opened = opening of `in` by a (2r+1)^2 square: erosion then dilation.
void open_grid(const float* in, TerrainGrid& g, uint32_t r) {
  terrain_line_filter(in, g.scratch, g.line, g.nx, g.ny, r, true, true);
  terrain_line_filter(g.scratch, g.opened, g.line, g.nx, g.ny, r, false, true);
  terrain_line_filter(g.opened, g.scratch, g.line, g.nx, g.ny, r, true, false);
  terrain_line_filter(g.scratch, g.opened, g.line, g.nx, g.ny, r, false, false);
}

// The progressive morphological filter: windows of half-width 1, 2, 4, ...
// cells up to params.max_window; the height tolerance grows with the window
// by the slope allowance, capped at dh_max. g.surface ends as the last opening.
uint32_t progressive_filter(TerrainGrid& g, const TerrainParams& params) {
  const uint32_t cells = g.nx * g.ny;
  for (uint32_t c = 0; c < cells; ++c) {
    g.off_ground[c] = 0;
    g.surface[c] = g.value[c];
  }
  uint32_t windows = 0;
  uint32_t r_prev = 0;
  for (uint32_t k = 0, r = 1; k < kMaxTerrainWindows; ++k, r *= 2u) {
    if (static_cast<float>(2u * r + 1u) * g.cell > params.max_window && k > 0) break;
    open_grid(g.surface, g, r);
    float dh = params.dh0;
    if (k > 0) dh += params.slope * static_cast<float>(2u * (r - r_prev)) * g.cell;
    dh = dh < params.dh_max ? dh : params.dh_max;
    for (uint32_t c = 0; c < cells; ++c) {
      if (!no_data(g.value[c]) && g.surface[c] - g.opened[c] > dh) g.off_ground[c] = 1;
      g.surface[c] = g.opened[c];
    }
    r_prev = r;
    ++windows;
  }
  return windows;
}

bool is_ground_cell(const TerrainGrid& g, uint32_t c) { return !no_data(g.value[c]) && !g.off_ground[c]; }

// out[c] for each cell off the ground: linear interpolation between the
// nearest ground cells before and after it along one axis (exact on planes
// of any slope, unlike the opening where the ground under a wide object is
// hidden); NaN without ground on both sides within max_gap cells.
void interpolate_line(TerrainGrid& g, float* out, bool along_x, uint32_t max_gap) {
  const uint32_t lines = along_x ? g.ny : g.nx;
  const uint32_t len = along_x ? g.nx : g.ny;
  const uint32_t step = along_x ? 1u : g.nx;
  for (uint32_t l = 0; l < lines; ++l) {
    const uint32_t base = along_x ? l * g.nx : l;
    uint32_t prev = len;  // none yet
    for (uint32_t i = 0; i < len; ++i) {
      const uint32_t c = base + i * step;
      out[c] = NAN;
      if (!is_ground_cell(g, c)) continue;
      out[c] = g.value[c];
      if (prev < len && i - prev > 1u && i - prev <= max_gap) {
        const float z0 = g.value[base + prev * step], z1 = g.value[c];
        for (uint32_t j = prev + 1u; j < i; ++j) {
          const float t = static_cast<float>(j - prev) / static_cast<float>(i - prev);
          out[base + j * step] = z0 + t * (z1 - z0);
        }
      }
      prev = i;
    }
  }
}

// Terrain surface: ground cells keep their own value; cells off the ground
// the mean of the row and column interpolations, or the last opening where
// neither reaches (g.surface holds it on entry).
void fill_terrain_surface(TerrainGrid& g, uint32_t max_gap) {
  interpolate_line(g, g.scratch, true, max_gap);
  interpolate_line(g, g.opened, false, max_gap);
  const uint32_t cells = g.nx * g.ny;
  for (uint32_t c = 0; c < cells; ++c) {
    if (is_ground_cell(g, c)) {
      g.surface[c] = g.value[c];
      continue;
    }
    const float a = g.scratch[c], b = g.opened[c];
    if (!no_data(a) && !no_data(b))
      g.surface[c] = 0.5f * (a + b);
    else if (!no_data(a))
      g.surface[c] = a;
    else if (!no_data(b))
      g.surface[c] = b;
  }
}

// The gap fill's reach: ground cells at most this far apart along a row or
// column are joined (the widest opening, and the snap's extra cells).
uint32_t gap_cells(const TerrainParams& params) {
  return static_cast<uint32_t>(params.max_window / params.cell) + 2u;
}

void clear_sums(TerrainGrid& g) {
  const uint32_t cells = g.nx * g.ny;
  for (uint32_t c = 0; c < cells; ++c) {
    g.value[c] = NAN;     // lowest z
    g.surface[c] = NAN;   // next lowest z
    g.scratch[c] = 0.0f;  // low band: sum
    g.opened[c] = 0.0f;   // low band: count
  }
}

}  // namespace

bool terrain_params_valid(const TerrainParams& p) {
  // The bounds of SceneConfig's terrain fields (limits.hpp, scene_fields.h).
  return p.cell >= kMinSceneTerrainCell && p.cell <= kMaxSceneTerrainCell && p.max_window >= p.cell &&
         p.max_window <= kMaxTerrainWindow && p.slope >= 0.0f && p.slope <= kMaxTerrainSlope &&
         p.dh0 >= 0.0f && p.dh_max >= p.dh0 && p.dh_max <= kMaxTerrainDh && p.ground_height >= 0.0f &&
         p.ground_height <= kMaxGroundHeight && p.low_band >= 0.0f && p.low_band <= kMaxTerrainDh &&
         p.noise_gap >= 0.0f && p.noise_gap <= kMaxTerrainDh &&
         (p.noise_gap == 0.0f || p.noise_gap >= p.low_band) && p.noise_reach >= 0.0f &&
         p.noise_reach <= kMaxTerrainNoiseReach && p.noise_support >= 1u &&
         p.noise_support <= kMaxTerrainNoiseSupport;
}

uint32_t terrain_noise_reach_cells(const TerrainParams& params) {
  if (!(params.noise_gap > 0.0f)) return 0;
  const float cells = std::ceil(params.noise_reach / params.cell);
  return cells >= static_cast<float>(kMaxTerrainNoiseCells) ? kMaxTerrainNoiseCells
                                                            : static_cast<uint32_t>(cells);
}

uint32_t terrain_reach_cells(const TerrainParams& params) {
  uint32_t reach = 0;
  for (uint32_t k = 0, r = 1; k < kMaxTerrainWindows; ++k, r *= 2u) {
    if (static_cast<float>(2u * r + 1u) * params.cell > params.max_window && k > 0) break;
    reach += 2u * r;  // erosion then dilation, each by r
  }
  const uint32_t gap = gap_cells(params);
  // The low-noise test's passes come first, each reaching its cells around.
  return (reach > gap ? reach : gap) + kTerrainNoisePasses * terrain_noise_reach_cells(params);
}

void TerrainGrid::carve(Arena& arena, uint32_t cells) {
  max_cells = cells;
  value = arena.alloc<float>(cells);
  surface = arena.alloc<float>(cells);
  scratch = arena.alloc<float>(cells);
  opened = arena.alloc<float>(cells);
  line = arena.alloc<float>(cells);  // one row or column: at most every cell
  off_ground = arena.alloc<uint8_t>(cells);
}

namespace {

// terrain_height_at where the point's four cell centres lie inside the grid
// and all have data (nearly every point): the general path's operations in
// its order, without its per-corner tests; false elsewhere. fx, fy >= 0, so
// truncation is the floor.
bool height_inside(const TerrainGrid& g, float fx, float fy, float* z) {
  if (!(fx >= 0.0f && fy >= 0.0f && fx < static_cast<float>(g.nx - 1u) && fy < static_cast<float>(g.ny - 1u)))
    return false;
  const uint32_t ix = static_cast<uint32_t>(fx), iy = static_cast<uint32_t>(fy);
  const float* row = g.surface + iy * g.nx + ix;
  const float v00 = row[0], v10 = row[1], v01 = row[g.nx], v11 = row[g.nx + 1u];
  if (no_data(v00) || no_data(v10) || no_data(v01) || no_data(v11)) return false;
  const float tx = fx - static_cast<float>(ix), ty = fy - static_cast<float>(iy);
  const float w00 = (1.0f - tx) * (1.0f - ty), w10 = tx * (1.0f - ty), w01 = (1.0f - tx) * ty, w11 = tx * ty;
  float sum = 0.0f, weight = 0.0f;
  sum += w00 * v00;
  weight += w00;
  sum += w10 * v10;
  weight += w10;
  sum += w01 * v01;
  weight += w01;
  sum += w11 * v11;
  weight += w11;
  if (!(weight > 1e-6f)) return false;
  *z = sum / weight;
  return true;
}

}  // namespace

float terrain_height_at(const TerrainGrid& g, float x, float y) {
  // Cell-centre coordinates: (x - x0) / cell - 0.5.
  const float fx = (x - g.x0) / g.cell - 0.5f;
  const float fy = (y - g.y0) / g.cell - 0.5f;
  float inside;
  if (height_inside(g, fx, fy, &inside)) return inside;
  const float bx = std::floor(fx), by = std::floor(fy);
  const float tx = fx - bx, ty = fy - by;
  float sum = 0.0f, weight = 0.0f;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const float cx = bx + static_cast<float>(dx), cy = by + static_cast<float>(dy);
      if (cx < 0.0f || cy < 0.0f || cx >= static_cast<float>(g.nx) || cy >= static_cast<float>(g.ny))
        continue;
      const float v = g.surface[static_cast<uint32_t>(cy) * g.nx + static_cast<uint32_t>(cx)];
      if (no_data(v)) continue;
      const float w = (dx ? tx : 1.0f - tx) * (dy ? ty : 1.0f - ty);
      sum += w * v;
      weight += w;
    }
  }
  if (weight > 1e-6f) return sum / weight;
  return g.surface[cell_coord(y, g.y0, g.cell, g.ny) * g.nx + cell_coord(x, g.x0, g.cell, g.nx)];
}

void TerrainParts::carve(Arena& arena, uint32_t max_cells) {
  whole.carve(arena, max_cells);
  part = arena.alloc<TerrainGrid>(kMaxTerrainParts);
  block_part = arena.alloc<uint8_t>(kMaxTerrainBlocks);
  count = 0;
}

namespace {

// Whether the part's grid, grown by a cell, holds (x, y): a point's own part
// always does, though float rounding may put it in the next block.
bool covers(const TerrainGrid& g, float x, float y) {
  return x >= g.x0 - g.cell && x < g.x0 + static_cast<float>(g.nx + 1u) * g.cell && y >= g.y0 - g.cell &&
         y < g.y0 + static_cast<float>(g.ny + 1u) * g.cell;
}

}  // namespace

const TerrainGrid* TerrainParts::part_at(float x, float y) const {
  const float fx = std::floor((x - x0) / block), fy = std::floor((y - y0) / block);
  if (!(fx >= -1.0f && fy >= -1.0f && fx <= static_cast<float>(bx) && fy <= static_cast<float>(by)))
    return nullptr;  // far outside, or NaN
  const int32_t ix = static_cast<int32_t>(fx), iy = static_cast<int32_t>(fy);
  // The point's own block first, then its neighbours.
  constexpr int32_t kOrder[3] = {0, -1, 1};
  for (int32_t dy : kOrder)
    for (int32_t dx : kOrder) {
      const int32_t i = ix + dx, j = iy + dy;
      if (i < 0 || j < 0 || i >= static_cast<int32_t>(bx) || j >= static_cast<int32_t>(by)) continue;
      const uint8_t p = block_part[static_cast<uint32_t>(j) * bx + static_cast<uint32_t>(i)];
      if (p != kNoTerrainPart && covers(part[p], x, y)) return &part[p];
    }
  return nullptr;
}

bool terrain_parts_begin(TerrainParts& parts, float cell, float x0, float y0, uint32_t block_cells,
                         uint32_t bx, uint32_t by) {
  if (bx == 0 || by == 0 || static_cast<uint64_t>(bx) * by > kMaxTerrainBlocks) return false;
  parts.count = 0;
  parts.cells = 0;
  parts.cell = cell;
  parts.x0 = x0;
  parts.y0 = y0;
  parts.block = static_cast<float>(block_cells) * cell;
  parts.bx = bx;
  parts.by = by;
  for (uint32_t b = 0; b < bx * by; ++b) parts.block_part[b] = kNoTerrainPart;
  return true;
}

uint8_t terrain_add_part(TerrainParts& parts, float x0, float y0, uint32_t nx, uint32_t ny) {
  const uint64_t need = static_cast<uint64_t>(nx) * ny;
  if (parts.count >= kMaxTerrainParts || nx == 0 || ny == 0 || parts.cells + need > parts.whole.max_cells)
    return kNoTerrainPart;
  TerrainGrid& g = parts.part[parts.count];
  const TerrainGrid& w = parts.whole;
  const uint32_t at = parts.cells;
  g.max_cells = static_cast<uint32_t>(need);
  g.value = w.value + at;
  g.surface = w.surface + at;
  g.scratch = w.scratch + at;
  g.opened = w.opened + at;
  g.line = w.line;  // one row or column at a time, shared
  g.off_ground = w.off_ground + at;
  g.nx = nx;
  g.ny = ny;
  g.x0 = x0;
  g.y0 = y0;
  g.cell = parts.cell;
  clear_sums(g);
  parts.cells += static_cast<uint32_t>(need);
  return static_cast<uint8_t>(parts.count++);
}

void terrain_put_cell(TerrainGrid& g, uint32_t ix, uint32_t iy, float lowest, float next, float band_sum,
                      float band_count) {
  const uint32_t c = iy * g.nx + ix;
  g.value[c] = lowest;
  g.surface[c] = next;
  g.scratch[c] = band_sum;
  g.opened[c] = band_count;
}

namespace {

// g.off_ground[c] = 1 where the cell's lowest (g.value) is low noise:
// apart from its next (g.surface), and held up by fewer than `support` of
// the cells within `reach` cells that have a floor, or by fewer than a
// quarter of them where that is less (a floor less than `gap` above it
// holds it; a cell judged noise has its next as floor); with none, nothing
// to judge by. Each pass sees the last one's judgements, so a pit beside a
// deeper one falls in the second. Returns the cells judged noise.
uint32_t mark_low_noise(TerrainGrid& g, float gap, uint32_t reach, uint32_t support) {
  const uint32_t cells = g.nx * g.ny;
  for (uint32_t c = 0; c < cells; ++c) g.off_ground[c] = 0;
  if (reach == 0) return 0;
  uint32_t noise = 0;
  for (uint32_t pass = 0; pass < kTerrainNoisePasses; ++pass)
    for (uint32_t y = 0; y < g.ny; ++y)
      for (uint32_t x = 0; x < g.nx; ++x) {
        const uint32_t c = y * g.nx + x;
        if (g.off_ground[c] || !terrain_lowest_apart(g.value[c], g.surface[c], gap)) continue;
        const float under = g.value[c] + gap;
        const uint32_t x0 = x > reach ? x - reach : 0u, x1 = x + reach < g.nx ? x + reach : g.nx - 1u;
        const uint32_t y0 = y > reach ? y - reach : 0u, y1 = y + reach < g.ny ? y + reach : g.ny - 1u;
        uint32_t around = 0, holding = 0;
        for (uint32_t v = y0; v <= y1 && holding < support; ++v)
          for (uint32_t u = x0; u <= x1 && holding < support; ++u) {
            const uint32_t n = v * g.nx + u;
            const float floor = g.off_ground[n] ? g.surface[n] : g.value[n];
            if (n == c || no_data(floor)) continue;
            ++around;
            holding += floor < under ? 1u : 0u;  // ground around as low: a dip, not noise
          }
        const uint32_t quarter = (around + 3u) / 4u;  // sparse ground: few cells around, each one counts
        if (around > 0 && holding < (support < quarter ? support : quarter)) {
          g.off_ground[c] = 1;
          ++noise;
        }
      }
  return noise;
}

// A cell's value from its sums: the mean of its low band over the band's
// base (terrain_band_base); a lowest apart from its next alone when kept,
// left out when noise (NaN: nothing else in the cell).
void cell_values(TerrainGrid& g, float gap) {
  const uint32_t cells = g.nx * g.ny;
  for (uint32_t c = 0; c < cells; ++c) {
    const float lowest = g.value[c], next = g.surface[c];
    const float band = g.opened[c] > 0.0f ? g.scratch[c] / g.opened[c] : 0.0f;
    if (!terrain_lowest_apart(lowest, next, gap))
      g.value[c] = lowest + band;
    else if (g.off_ground[c])
      g.value[c] = no_data(next) ? NAN : next + band;
  }
}

}  // namespace

// Each part: its cells' values from their sums (low noise left out), the
// progressive filter, the gaps filled.
uint32_t terrain_finish(TerrainParts& parts, const TerrainParams& params, uint32_t* noise_cells) {
  uint32_t windows = 0;
  const uint32_t reach = terrain_noise_reach_cells(params);
  for (uint32_t k = 0; k < parts.count; ++k) {
    TerrainGrid& g = parts.part[k];
    const uint32_t noise = mark_low_noise(g, params.noise_gap, reach, params.noise_support);
    if (noise_cells != nullptr) *noise_cells += noise;
    cell_values(g, params.noise_gap);
    windows = progressive_filter(g, params);
    fill_terrain_surface(g, gap_cells(params));
  }
  return windows;
}

float terrain_height_at(const TerrainParts& parts, float x, float y) {
  const TerrainGrid* g = parts.part_at(x, y);
  return g == nullptr ? NAN : terrain_height_at(*g, x, y);
}

uint32_t terrain_heights(const TerrainParts& parts, const float* xyz, uint32_t n, float ground_height,
                         float* height, uint8_t* ground) {
  uint32_t on_ground = 0;
  const TerrainGrid* only = parts.count == 1 ? &parts.part[0] : nullptr;
  for (uint32_t i = 0; i < n; ++i) {
    const float* p = xyz + 3u * i;
    const float z = only ? terrain_height_at(*only, p[0], p[1]) : terrain_height_at(parts, p[0], p[1]);
    height[i] = p[2] - z;
    ground[i] = height[i] <= ground_height ? 1u : 0u;
    on_ground += ground[i];
  }
  return on_ground;
}

}  // namespace spinhash
