// The stream's terrain cells (scene/terrain_cells.hpp) against the grid a
// strip's own points give (geometry/terrain.hpp): the same footprint, cell
// values, filtered surface and heights, bit for bit, on sloped terrain with
// a bump, a curb and vehicle-sized boxes; summed in rows as the stream does
// (each cell once, the ring's slots reused along the track); and the
// configuration rule that keeps every vehicle whole in a window's gather.
#include <doctest/doctest.h>

#include <cmath>
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
  TerrainGrid grid;
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

// The grid over the points of the ring inside `rect`, as the tile API
// builds a strip's (local floats at (s0, t0)), filtered.
void grid_from_points(const PointRing& ring, const FrameRect& rect, double s0, double t0, TerrainGrid& g,
                      std::vector<float>* local) {
  local->clear();
  for (uint32_t i = 0; i < ring.count; ++i) {
    double p[3];
    ring.get(i, p);
    if (!rect.holds(p[0], p[1])) continue;
    local->insert(local->end(),
                  {static_cast<float>(p[0] - s0), static_cast<float>(p[1] - t0), static_cast<float>(p[2])});
  }
  float lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t i = 0; i < local->size(); i += 3)
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::fmin(lo[a], (*local)[i + a]);
      hi[a] = std::fmax(hi[a], (*local)[i + a]);
    }
  REQUIRE(terrain_begin(g, kCell, lo, hi));
  for (size_t i = 0; i < local->size(); i += 3) terrain_add_lowest(g, local->data() + i);
  for (size_t i = 0; i < local->size(); i += 3) terrain_add_low_band(g, local->data() + i);
  terrain_finish(g, TerrainParams{}, nullptr);
}

struct Snapshot {
  uint32_t nx = 0, ny = 0;
  float x0 = 0, y0 = 0;
  std::vector<float> value, surface, height;
};

Snapshot snapshot(const TerrainGrid& g, const std::vector<float>& local) {
  Snapshot s{g.nx, g.ny, g.x0, g.y0, {}, {}, {}};
  s.value.assign(g.value, g.value + g.nx * g.ny);
  s.surface.assign(g.surface, g.surface + g.nx * g.ny);
  for (size_t i = 0; i < local.size(); i += 3)
    s.height.push_back(local[i + 2] - terrain_height_at(g, local[i], local[i + 1]));
  return s;
}

bool same_floats(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
  return true;
}

}  // namespace

TEST_CASE("terrain cells: a strip's grid from the summed cells equals the grid from its points") {
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
    grid_from_points(c.ring, rect, s0, t0, c.grid, &local);
    const Snapshot from_points = snapshot(c.grid, local);
    REQUIRE(c.cells.fill(rect, s0, t0, kCell, c.grid) == Status::kOk);
    terrain_finish(c.grid, TerrainParams{}, nullptr);
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
  const TerrainGrid full = c.grid;
  c.grid.max_cells = 1000;
  CHECK(c.cells.fill(FrameRect{-kMargin, kRow + kMargin, -70.0, 70.0}, -kMargin, -70.0, kCell, c.grid) ==
        Status::kTileTooLarge);
  c.grid = full;
  c.cells.sum(c.ring, 200.0 - kMargin, 200.0 + kRow + kMargin);  // along the track, beyond the tile
  CHECK(c.cells.fill(FrameRect{200.0 - kMargin, 200.0 + kRow + kMargin, -70.0, 70.0}, 200.0 - kMargin, -70.0,
                     kCell, c.grid) == Status::kEmptyCloud);
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
