// Low noise in the terrain (geometry/terrain.hpp, noise_gap and
// noise_reach), run as the scene stream runs it: unclassified points
// metres under the ground (multipath returns) are left out of the terrain,
// which otherwise sinks wherever they lie closer than the widest opening;
// ground seen through a crown one point per cell, a ditch and a lone point
// stay as they are.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/terrain.hpp"
#include "support/scene_fixtures.hpp"
#include "support/stream_terrain.hpp"
#include "util/rng.hpp"

using namespace spinhash;
using namespace spinhash::test;

namespace {

// `count` copies of random ground points of the tile, each 2 to 20 m lower:
// appended after the tile's own points.
std::vector<double> with_low_noise(const Tile& tile, uint32_t count, uint64_t seed) {
  std::vector<size_t> ground;
  for (size_t i = 0; i < tile.ground.size(); ++i)
    if (tile.ground[i]) ground.push_back(i);
  std::vector<double> xyz = tile.xyz;
  Pcg32 rng(seed);
  for (uint32_t k = 0; k < count; ++k) {
    const size_t i = ground[rng.below(static_cast<uint32_t>(ground.size()))];
    xyz.insert(xyz.end(),
               {tile.xyz[3 * i], tile.xyz[3 * i + 1], tile.xyz[3 * i + 2] - 2.0 - 18.0 * rng.uniform()});
  }
  return xyz;
}

GroundScore score(const Tile& tile, const StreamTerrain& c) {
  TerrainShape t;
  t.slope_deg = 8.0;
  return ground_score(tile, t, c);
}

}  // namespace

TEST_CASE("terrain noise: points metres under the ground are left out, and the ground stays ground") {
  const Tile tile = terrain_sample_tile(8.0);  // a car, a building and a crate
  TerrainParams off;
  off.noise_gap = 0.0f;
  // One low point per 18 m2 of the tile: pits closer than the widest
  // opening, among them two 0.5 m apart at one depth (-18 m).
  const std::vector<double> noisy = with_low_noise(tile, 32, 11);
  const StreamTerrain on = stream_terrain(noisy, TerrainParams{}), without = stream_terrain(noisy, off);
  REQUIRE(on.status == Status::kOk);
  REQUIRE(without.status == Status::kOk);
  const double recall = score(tile, on).recall(), precision = score(tile, on).precision(),
               sunk = score(tile, without).recall();
  CAPTURE(recall);
  CAPTURE(precision);
  CAPTURE(sunk);
  CHECK(recall >= 0.98);
  CHECK(precision >= 0.98);
  CHECK(on.noise_cells >= 30u);  // each pit in its own cell, but where two share one
  CHECK(on.noise_cells <= 32u);
  CHECK(sunk < 0.9);  // without the test the terrain sinks to the pits
  // Kept by one cell as low, the pair would hold each other up and sink
  // the terrain around them.
  TerrainParams one = TerrainParams{};
  one.noise_support = 1;
  CHECK(score(tile, stream_terrain(noisy, one)).recall() < 0.95);
  CHECK(without.noise_cells == 0u);
  // The clean tile: no cell judged noise, every height as without the test.
  const StreamTerrain clean = stream_terrain(tile.xyz, TerrainParams{}),
                      clean_off = stream_terrain(tile.xyz, off);
  CHECK(clean.noise_cells == 0u);
  CHECK(clean.height == clean_off.height);
}

TEST_CASE("terrain noise: ground seen one point per cell under a crown, a ditch and a lone point stay") {
  TerrainShape t;  // flat, with the default bump and curb
  Tile tile;
  add_terrain(tile, t, 12.0, 0.2, 0.03, 7);
  // A crown 8 m across over (-4, 4): its ground seen through it only every
  // 0.7 m (one point in most cells), the crown's points 3.5 to 8 m up.
  // A ditch 1.5 m deep and 1 m wide across the tile at x = 6, seen along
  // its floor every 0.45 m (one point in a cell, nothing else there): each
  // floor point lies far under the banks, as a pit would, but along the
  // ditch two or more of its neighbours are as low (noise_support), even at
  // its ends.
  std::vector<size_t> under, ditch;
  {
    Tile open;
    for (size_t i = 0; i < tile.ground.size(); ++i) {
      const double* p = &tile.xyz[3 * i];
      if (std::hypot(p[0] + 4.0, p[1] - 4.0) < 4.0 || std::fabs(p[0] - 6.0) < 0.5) continue;
      open.add(p[0], p[1], p[2], true, -1);
    }
    for (double x = -8.0; x <= 0.0; x += 0.7)
      for (double y = 0.0; y <= 8.0; y += 0.7)
        if (std::hypot(x + 4.0, y - 4.0) < 4.0) {
          open.add(x, y, terrain_z(t, x, y), true, -1);
          under.push_back(open.ground.size() - 1u);
        }
    for (double y = -11.9; y <= 11.9; y += 0.45) {
      open.add(6.1, y, terrain_z(t, 6.1, y) - 1.5, true, -1);
      ditch.push_back(open.ground.size() - 1u);
    }
    add_tree(open, t, -4.0, 4.0, -4.0, 4.0, 5.75, 2.25, 0.25);
    tile = open;
  }
  tile.add(40.0, 40.0, -3.0, true, -1);  // a lone point: nothing around to judge it by
  const StreamTerrain c = stream_terrain(tile.xyz, TerrainParams{});
  REQUIRE(c.status == Status::kOk);
  uint32_t under_ground = 0, ditch_same = 0, crown_ground = 0, crown = 0;
  for (size_t i : under) under_ground += c.ground[i];
  TerrainParams off;
  off.noise_gap = 0.0f;
  const StreamTerrain without = stream_terrain(tile.xyz, off);
  for (size_t i : ditch) ditch_same += c.height[i] == without.height[i];  // its floor not left out
  for (size_t i = 0; i < tile.object.size(); ++i)
    if (tile.object[i] >= 0 && tile.xyz[3 * i + 2] > 3.0) {
      ++crown;
      crown_ground += c.ground[i];
    }
  CAPTURE(c.noise_cells);
  CHECK(under_ground == under.size());  // left out or not, the terrain under them is theirs
  CHECK(ditch_same == ditch.size());
  CHECK(crown > 100u);
  CHECK(crown_ground == 0u);
  CHECK(c.ground.back() == 1u);
  CHECK(c.height.back() == doctest::Approx(0.0f));
}

TEST_CASE("terrain noise: sparse ground on a steep slope, one point in a cell, is never noise") {
  // One point per m2 on a 35 degree slope: a cell has a few cells around
  // it within the reach, some of them more than the gap above; each that
  // is as low counts.
  TerrainShape t;
  t.slope_deg = 35.0;
  Tile tile;
  add_terrain(tile, t, 12.0, 1.0, 0.05, 5);
  TerrainParams off;
  off.noise_gap = 0.0f;
  const StreamTerrain on = stream_terrain(tile.xyz, TerrainParams{}), without = stream_terrain(tile.xyz, off);
  REQUIRE(on.status == Status::kOk);
  CHECK(on.noise_cells == 0u);
  CHECK(on.height == without.height);
}
