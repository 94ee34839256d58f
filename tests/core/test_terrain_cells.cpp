// The stream's terrain cells (scene/terrain_cells.hpp) against the grid
// their definition gives over a strip's own points (each cell's lowest z
// and next lowest, then the mean of the points within the low band above
// the band's base): the same
// footprint, cell values, filtered surface and heights, bit for bit, on
// sloped terrain with a bump, a curb and vehicle-sized boxes; summed in
// rows as the stream does (each cell once, the ring's slots reused along
// the track); and the configuration rule that keeps every vehicle whole in
// a window's gather.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "scene/terrain_cells.hpp"
#include "spinhash/scene_stream.hpp"
#include "support/scene_fixtures.hpp"

using namespace spinhash;
using namespace spinhash::test;

namespace {

constexpr float kCell = 0.5f;              // m: the scene's terrain cell
constexpr double kRow = 32.0;              // m: a core along the track
constexpr double kMargin = 40.0;           // m: the terrain's margin
constexpr uint32_t kGridCells = 1u << 17;  // a strip's grid

struct Carved {
  std::vector<uint8_t> bytes;
  TerrainParts grid;
  TerrainCells cells;
  PointRing ring;
};

// Carves a grid, the cells (a strip of kRow + 2 kMargin along, `width`
// across) and a ring of `points` from one host buffer.
void carve(Carved& c, double width, uint32_t points) {
  Arena counter;
  c.grid.carve(counter, kGridCells);
  c.cells.carve(counter, kCell, kRow + 2.0 * kMargin, width);
  c.ring.carve(counter, points);
  c.bytes.assign(counter.used() + 64, 0);
  Arena arena(c.bytes.data(), c.bytes.size());
  c.grid.carve(arena, kGridCells);
  c.cells.carve(arena, kCell, kRow + 2.0 * kMargin, width);
  c.ring.carve(arena, points);
}

Tile strip_tile() {
  TerrainShape t;
  t.slope_deg = 6.0;
  t.bump_x = 30.0;
  t.bump_y = 4.0;
  Tile tile;
  add_terrain_rect(tile, t, -45.0, 110.0, -30.0, 30.0, 0.3, 0.03, 7);
  add_box(tile, t, 31.9, 0.5, 0.3, 4.5, 1.8, 1.5, 0.2, 0.15);    // across the row edge at 32
  add_box(tile, t, 70.0, -8.0, 1.1, 12.0, 2.5, 3.2, 0.3, 0.15);  // a bus
  return tile;
}

// The grid the definition gives over the points of the ring inside `rect`
// (cells of the frame's lattice from t_min across): one part over the
// cells that hold points, each cell's lowest and next lowest z, then its
// points within the low band above its base (the next where the lowest
// lies noise_gap under it or alone, else the lowest), in the points'
// order; filtered. `local`: the points in
// the local frame at (s0, t0).
void grid_from_points(const PointRing& ring, const FrameRect& rect, double t_min, double s0, double t0,
                      TerrainParts& g, std::vector<float>* local) {
  using Cell = std::pair<int64_t, int64_t>;
  struct Sums {
    float lowest = NAN, next = NAN, sum = 0.0f, count = 0.0f;
  };
  std::map<Cell, Sums> cells;
  std::vector<std::pair<Cell, float>> points;
  local->clear();
  for (uint32_t i = 0; i < ring.count; ++i) {
    double p[3];
    ring.get(i, p);
    if (!rect.holds(p[0], p[1])) continue;
    local->insert(local->end(),
                  {static_cast<float>(p[0] - s0), static_cast<float>(p[1] - t0), static_cast<float>(p[2])});
    const Cell c{static_cast<int64_t>(std::floor(p[0] / kCell)),
                 static_cast<int64_t>(std::floor((p[1] - t_min) / kCell))};
    points.push_back({c, static_cast<float>(p[2])});
    Sums& sums = cells[c];
    const float z = points.back().second;
    if (std::isnan(sums.lowest) || z < sums.lowest) {
      sums.next = sums.lowest;
      sums.lowest = z;
    } else if (std::isnan(sums.next) || z < sums.next) {
      sums.next = z;
    }
  }
  const TerrainParams params;
  for (const auto& [c, z] : points) {
    Sums& sums = cells[c];
    const bool apart = std::isnan(sums.next) || sums.next - sums.lowest > params.noise_gap;
    const float base = apart ? sums.next : sums.lowest;
    if (!(z >= base) || z > base + params.low_band) continue;
    sums.sum += z - base;
    sums.count += 1.0f;
  }
  int64_t lo[2] = {INT64_MAX, INT64_MAX}, hi[2] = {INT64_MIN, INT64_MIN};
  for (const auto& [c, sums] : cells) {
    lo[0] = std::min(lo[0], c.first), hi[0] = std::max(hi[0], c.first);
    lo[1] = std::min(lo[1], c.second), hi[1] = std::max(hi[1], c.second);
  }
  REQUIRE(terrain_parts_begin(g, kCell, 0.0f, 0.0f, 1u << 20, 1, 1));
  const uint8_t part =
      terrain_add_part(g, static_cast<float>(static_cast<double>(lo[0]) * kCell - s0),
                       static_cast<float>(t_min + static_cast<double>(lo[1]) * kCell - t0),
                       static_cast<uint32_t>(hi[0] - lo[0] + 1), static_cast<uint32_t>(hi[1] - lo[1] + 1));
  REQUIRE(part == 0u);
  g.block_part[0] = part;
  for (const auto& [c, sums] : cells)
    terrain_put_cell(g.part[0], static_cast<uint32_t>(c.first - lo[0]),
                     static_cast<uint32_t>(c.second - lo[1]), sums.lowest, sums.next, sums.sum, sums.count);
  terrain_finish(g, TerrainParams{});
}

struct Snapshot {
  uint32_t nx = 0, ny = 0;
  float x0 = 0, y0 = 0;
  std::vector<float> value, surface, height;
};

Snapshot snapshot(const TerrainParts& parts, const std::vector<float>& local) {
  REQUIRE(parts.count == 1u);  // one stretch of ground
  const TerrainGrid& g = parts.part[0];
  Snapshot s{g.nx, g.ny, g.x0, g.y0, {}, {}, {}};
  s.value.assign(g.value, g.value + g.nx * g.ny);
  s.surface.assign(g.surface, g.surface + g.nx * g.ny);
  for (size_t i = 0; i < local.size(); i += 3)
    s.height.push_back(local[i + 2] - terrain_height_at(parts, local[i], local[i + 1]));
  return s;
}

bool same_floats(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
  return true;
}

}  // namespace

TEST_CASE("terrain cells: a strip's grid from the summed cells equals the grid its points define") {
  const Tile tile = strip_tile();
  const uint32_t n = static_cast<uint32_t>(tile.ground.size());
  Carved c;
  carve(c, 60.0 + 2.0 * kMargin, n);
  for (uint32_t i = 0; i < n; ++i) c.ring.push(tile.xyz.data() + 3u * i);  // the frame is the tile's
  c.cells.start(-30.0 - kMargin);
  std::vector<float> local;
  uint32_t compared = 0;
  // Rows summed in order, as the stream does: each new row sums only the
  // cells its lookahead adds, in slots the rows behind no longer need.
  for (int64_t k = -1; k <= 2; ++k) {
    CAPTURE(k);
    const double s_lo = static_cast<double>(k) * kRow - kMargin,
                 s_hi = static_cast<double>(k + 1) * kRow + kMargin;
    c.cells.sum(c.ring, s_lo, s_hi);
    CHECK(c.cells.summed_edge() == s_hi);
    const FrameRect rect{s_lo, s_hi, -30.0 - kMargin, 30.0 + kMargin};
    const double s0 = s_lo, t0 = rect.t0;
    grid_from_points(c.ring, rect, c.cells.t_min, s0, t0, c.grid, &local);
    const Snapshot from_points = snapshot(c.grid, local);
    REQUIRE(c.cells.fill(rect, rect, s0, t0, terrain_reach_cells(TerrainParams{}), c.grid) == Status::kOk);
    terrain_finish(c.grid, TerrainParams{});
    const Snapshot from_cells = snapshot(c.grid, local);
    CHECK(from_cells.nx == from_points.nx);
    CHECK(from_cells.ny == from_points.ny);
    CHECK(from_cells.x0 == from_points.x0);
    CHECK(from_cells.y0 == from_points.y0);
    CHECK(same_floats(from_cells.value, from_points.value));
    CHECK(same_floats(from_cells.surface, from_points.surface));
    CHECK(same_floats(from_cells.height, from_points.height));
    compared += static_cast<uint32_t>(from_cells.height.size());
  }
  CHECK(compared > n);  // the rows overlap: most points are compared in several strips
}

TEST_CASE("terrain cells: a strip without points is kEmptyCloud, a grid too small kTileTooLarge") {
  const Tile tile = strip_tile();
  const uint32_t n = static_cast<uint32_t>(tile.ground.size());
  Carved c;
  carve(c, 60.0 + 2.0 * kMargin, n);
  for (uint32_t i = 0; i < n; ++i) c.ring.push(tile.xyz.data() + 3u * i);
  c.cells.start(-30.0 - kMargin);
  c.cells.sum(c.ring, -kMargin, kRow + kMargin);
  const uint32_t reach = terrain_reach_cells(TerrainParams{});
  const uint32_t full = c.grid.whole.max_cells;
  c.grid.whole.max_cells = 1000;
  CHECK(c.cells.fill(FrameRect{-kMargin, kRow + kMargin, -70.0, 70.0},
                     FrameRect{-kMargin, kRow + kMargin, -70.0, 70.0}, -kMargin, -70.0, reach,
                     c.grid) == Status::kTileTooLarge);
  c.grid.whole.max_cells = full;
  c.cells.sum(c.ring, 200.0 - kMargin, 200.0 + kRow + kMargin);  // along the track, beyond the tile
  const FrameRect beyond{200.0 - kMargin, 200.0 + kRow + kMargin, -70.0, 70.0};
  CHECK(c.cells.fill(beyond, beyond, 200.0 - kMargin, -70.0, reach, c.grid) == Status::kEmptyCloud);
}

TEST_CASE("scene config: the object margin keeps every vehicle whole and stays within the terrain's") {
  SceneConfig c;
  CHECK(scene_config_valid(c));
  CHECK(2.0f * c.object_margin >= std::hypot(c.max_length, c.max_width));
  c.object_margin = 6.5f;  // a bus cut on the diagonal could pass the gates
  CHECK_FALSE(scene_config_valid(c));
  c.object_margin = c.window_margin + 1.0f;
  CHECK_FALSE(scene_config_valid(c));
  c.object_margin = 7.0f;
  c.max_length = 20.0f;  // longer vehicles need a wider gather
  CHECK_FALSE(scene_config_valid(c));
  c.object_margin = 10.5f;
  CHECK(scene_config_valid(c));
  c.window_margin = 40.25f;  // off the terrain lattice
  CHECK_FALSE(scene_config_valid(c));
}
