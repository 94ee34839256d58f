// Terrain classifier (geometry/terrain.hpp), run as the scene stream runs it
// (support/stream_terrain.hpp: cell sums, parts, filter, heights): ground
// recall and precision on sloped terrain with a bump and a curb, objects
// lifted off it, heights above the terrain, a footprint larger than the
// grid refused, and parts that follow the points.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "geometry/terrain.hpp"
#include "support/scene_fixtures.hpp"
#include "support/stream_terrain.hpp"

using namespace spinhash;
using namespace spinhash::test;

namespace {

StreamTerrain classify(const Tile& tile, const TerrainParams& p, uint32_t max_cells = 1u << 14) {
  return stream_terrain(tile.xyz, p, max_cells);
}

}  // namespace

TEST_CASE("terrain: ground recall and precision on 0, 8 and 15 degree slopes with a bump and a curb") {
  for (double slope : {0.0, 8.0, 15.0}) {
    CAPTURE(slope);
    const Tile tile = terrain_sample_tile(slope);
    const StreamTerrain c = classify(tile, TerrainParams{});
    REQUIRE(c.status == Status::kOk);
    TerrainShape t;
    t.slope_deg = slope;
    const GroundScore s = ground_score(tile, t, c);
    const double recall = s.recall(), precision = s.precision();
    CAPTURE(recall);
    CAPTURE(precision);
    CHECK(recall >= 0.98);
    CHECK(precision >= 0.98);
    CHECK(c.points_ground == s.tp + s.fp);
    CHECK(c.windows >= 3u);
    CHECK(c.parts == 1u);  // one stretch of ground
  }
}

TEST_CASE("terrain: heights above the terrain on a 15 degree slope (car roof, building roof, crate)") {
  const Tile tile = terrain_sample_tile(15.0);
  const StreamTerrain c = classify(tile, TerrainParams{});
  REQUIRE(c.status == Status::kOk);
  float top[3] = {-1e9f, -1e9f, -1e9f};
  for (size_t i = 0; i < tile.object.size(); ++i)
    if (tile.object[i] >= 0) top[tile.object[i]] = std::fmax(top[tile.object[i]], c.height[i]);
  CHECK(top[0] == doctest::Approx(1.5).epsilon(0.1));  // 0.3 clearance + 1.2
  CHECK(top[1] == doctest::Approx(5.0).epsilon(0.1));
  CHECK(top[2] == doctest::Approx(0.6).epsilon(0.25));  // small: the opening keeps part of it
  // The crate's points above 0.3 m are off the ground, but for its bottom
  // rim: a wall standing on the ground lifts the low mean of its cells a little.
  TerrainShape t;
  t.slope_deg = 15.0;
  uint32_t crate = 0, crate_off = 0;
  for (size_t i = 0; i < tile.object.size(); ++i)
    if (tile.object[i] == 2 &&
        tile.xyz[3 * i + 2] - terrain_z(t, tile.xyz[3 * i], tile.xyz[3 * i + 1]) > 0.3) {
      ++crate;
      crate_off += c.ground[i] ? 0u : 1u;
    }
  CHECK(crate_off >= 0.85 * crate);
}

TEST_CASE("terrain: a footprint needing more cells than the grid holds is kTileTooLarge") {
  const Tile tile = terrain_sample_tile(0.0);
  // 49.2 x 49.2 cells, and up to one more each way where the grid's origin
  // snaps down to the cell lattice.
  CHECK(classify(tile, TerrainParams{}, 2000).status == Status::kTileTooLarge);
  CHECK(classify(tile, TerrainParams{}, 2601).status == Status::kOk);
  TerrainParams bad;
  bad.cell = 0.0f;
  CHECK(!terrain_params_valid(bad));
}

TEST_CASE("terrain: parts follow the points: far-apart patches are filtered each on its own footprint") {
  // Two patches of the sample tile 3 km apart across, and a lone point
  // between them: three parts, a few thousand cells, not the 6 million of
  // one grid over their span; each patch's heights are those it gives alone.
  const Tile tile = terrain_sample_tile(8.0);
  std::vector<double> near = tile.xyz, far = tile.xyz, both = tile.xyz;
  for (size_t i = 1; i < far.size(); i += 3) far[i] += 3000.0;
  both.insert(both.end(), far.begin(), far.end());
  both.insert(both.end(), {5.0, 1500.0, 3.0});
  const StreamTerrain alone_near = stream_terrain(near, TerrainParams{}),
                      alone_far = stream_terrain(far, TerrainParams{});
  const StreamTerrain together = stream_terrain(both, TerrainParams{});
  REQUIRE(together.status == Status::kOk);
  CHECK(together.parts == 3u);
  CHECK(together.cells == alone_near.cells + alone_far.cells + 1u);
  const size_t n = near.size() / 3;
  bool same = true;
  for (size_t i = 0; i < n; ++i)
    same =
        same && together.height[i] == alone_near.height[i] && together.height[n + i] == alone_far.height[i];
  CHECK(same);
  CHECK(together.ground.back() == 1u);  // the lone point is its own ground
}

namespace {

// The direct scan, the opening's definition: 2r + 1 cells per output cell.
void direct_line_filter(const std::vector<float>& in, std::vector<float>& out, uint32_t nx, uint32_t ny,
                        uint32_t r, bool along_x, bool erode) {
  const uint32_t lines = along_x ? ny : nx, len = along_x ? nx : ny, step = along_x ? 1u : nx;
  for (uint32_t l = 0; l < lines; ++l) {
    const uint32_t base = along_x ? l * nx : l;
    for (uint32_t i = 0; i < len; ++i) {
      const uint32_t lo = i > r ? i - r : 0u, hi = i + r < len ? i + r : len - 1u;
      float best = NAN;
      for (uint32_t j = lo; j <= hi; ++j) {
        const float v = in[base + j * step];
        if (std::isnan(v)) continue;
        if (std::isnan(best) || (erode ? v < best : v > best)) best = v;
      }
      out[base + i * step] = best;
    }
  }
}

}  // namespace

TEST_CASE("terrain: the opening's line filter equals the direct scan for every window, with gaps") {
  uint64_t state = 12345;
  auto next = [&state]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<uint32_t>(state >> 33);
  };
  const uint32_t sizes[][2] = {{1, 1}, {1, 37}, {37, 1}, {5, 9}, {33, 17}, {64, 40}};
  for (const auto& size : sizes) {
    const uint32_t nx = size[0], ny = size[1];
    std::vector<float> in(nx * ny), fast(nx * ny), slow(nx * ny), line(nx > ny ? nx : ny);
    for (float& v : in) v = next() % 5 == 0 ? NAN : static_cast<float>(next() % 1000) * 0.01f - 3.0f;
    for (uint32_t r : {1u, 2u, 3u, 4u, 8u, 16u, 40u})
      for (int axis = 0; axis < 2; ++axis)
        for (int erode = 0; erode < 2; ++erode) {
          CAPTURE(nx);
          CAPTURE(ny);
          CAPTURE(r);
          terrain_line_filter(in.data(), fast.data(), line.data(), nx, ny, r, axis == 0, erode == 1);
          direct_line_filter(in, slow, nx, ny, r, axis == 0, erode == 1);
          bool same = true;
          for (size_t c = 0; c < in.size(); ++c)
            same = same && (std::isnan(fast[c]) ? std::isnan(slow[c]) : fast[c] == slow[c]);
          CHECK(same);
        }
  }
}

namespace {

// terrain_height_at's definition: bilinear over the four cell centres
// around (x, y), skipping cells outside the grid or without data, else the
// point's own cell (the general path, written out here as the reference of
// the fast path for points whose four cells all have data).
float reference_height(const TerrainGrid& g, float x, float y) {
  const float fx = (x - g.x0) / g.cell - 0.5f, fy = (y - g.y0) / g.cell - 0.5f;
  const float bx = std::floor(fx), by = std::floor(fy), tx = fx - bx, ty = fy - by;
  float sum = 0.0f, weight = 0.0f;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const float cx = bx + static_cast<float>(dx), cy = by + static_cast<float>(dy);
      if (cx < 0.0f || cy < 0.0f || cx >= static_cast<float>(g.nx) || cy >= static_cast<float>(g.ny))
        continue;
      const float v = g.surface[static_cast<uint32_t>(cy) * g.nx + static_cast<uint32_t>(cx)];
      if (std::isnan(v)) continue;
      const float w = (dx ? tx : 1.0f - tx) * (dy ? ty : 1.0f - ty);
      sum += w * v;
      weight += w;
    }
  if (weight > 1e-6f) return sum / weight;
  auto coord = [](float v, float v0, float cell, uint32_t count) {
    const float c = (v - v0) / cell;
    if (!(c > 0.0f)) return 0u;
    const uint32_t i = static_cast<uint32_t>(c);
    return i < count ? i : count - 1u;
  };
  return g.surface[coord(y, g.y0, g.cell, g.ny) * g.nx + coord(x, g.x0, g.cell, g.nx)];
}

}  // namespace

// Bit for bit where the compiler fuses no multiply-add (x86-64); where it
// does (aarch64, powerpc), the fast path and the reference may fuse
// differently, so there they agree to float rounding.
constexpr float kFusedRounding = 1e-4f;  // m, on heights of ~300 m (a few ulp)

TEST_CASE("terrain: the height lookup equals its definition, inside, at the edges and by holes") {
  constexpr uint32_t kNx = 23, kNy = 17;
  std::vector<float> surface(kNx * kNy);
  uint64_t state = 99;
  auto uniform = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state >> 40) / static_cast<float>(1u << 24);
  };
  for (float& v : surface) v = uniform() < 0.1f ? NAN : 300.0f + 5.0f * uniform();  // holes: no data
  TerrainGrid g;
  g.surface = surface.data();
  g.nx = kNx;
  g.ny = kNy;
  g.cell = 0.5f;
  g.x0 = -3.5f;
  g.y0 = 12.0f;
  uint32_t compared = 0;
  for (int i = 0; i < 20000; ++i) {  // beyond the grid on every side, and exactly on cell centres
    float x = g.x0 - 1.0f + (kNx * g.cell + 2.0f) * uniform(),
          y = g.y0 - 1.0f + (kNy * g.cell + 2.0f) * uniform();
    if (i % 10 == 0) x = g.x0 + g.cell * (0.5f + static_cast<float>(i % kNx));
    const float got = terrain_height_at(g, x, y), want = reference_height(g, x, y);
    if (std::isnan(want)) {
      CHECK(std::isnan(got));
    } else {
#if defined(__x86_64__) && !defined(__FMA__)
      CHECK(got == want);
#else
      CHECK(std::fabs(got - want) <= kFusedRounding);
#endif
      ++compared;
    }
  }
  CHECK(compared > 15000u);
}
