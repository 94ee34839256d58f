// Ground removal (geometry/ground.hpp) on known geometry, and through
// recognize(): a toy vehicle standing on a ground square, level or tilted by
// 15 degrees, is recognised as well as without it.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "geometry/ground.hpp"
#include "spinhash/recognizer.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/scene_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr float kClearance = 0.25f;

// A 4 x 2 x 1.5 m box standing on z = 0, above a level ground square.
std::vector<float> box_on_ground(float ground_half) {
  std::vector<float> pts = test::box_surface(4.0f, 2.0f, 1.5f, 0.1f);
  for (size_t i = 2; i < pts.size(); i += 3) pts[i] += 0.75f;  // bottom face at z = 0
  std::vector<float> ground = test::plane_grid(ground_half, 0.1f);
  pts.insert(pts.end(), ground.begin(), ground.end());
  return pts;
}

// remove_ground with its grid and scratch carved from host buffers.
uint32_t remove(std::vector<float>& pts, uint32_t n, float clearance) {
  Arena counter;
  TerrainGrid g;
  g.carve(counter, kQueryTerrainCells);
  std::vector<uint8_t> ws(counter.used() + 64);
  Arena arena(ws.data(), ws.size());
  g.carve(arena, kQueryTerrainCells);
  std::vector<float> height(n);
  std::vector<uint8_t> ground(n);
  return remove_ground(pts.data(), n, clearance, g, height.data(), ground.data());
}

uint32_t count_near(const std::vector<float>& pts, uint32_t n, float z) {
  uint32_t c = 0;
  for (uint32_t i = 0; i < n; ++i) c += std::fabs(pts[3u * i + 2u] - z) < 1e-3f ? 1u : 0u;
  return c;
}

uint32_t count_at_most(const std::vector<float>& pts, uint32_t n, float z) {
  uint32_t c = 0;
  for (uint32_t i = 0; i < n; ++i) c += pts[3u * i + 2u] <= z ? 1u : 0u;
  return c;
}

}  // namespace

TEST_CASE("the ground and the lowest clearance of an object on it are dropped, nothing else") {
  std::vector<float> pts = box_on_ground(5.0f);
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  const uint32_t low = count_at_most(pts, n, kClearance - 0.02f);   // surely dropped
  const uint32_t high = count_at_most(pts, n, kClearance + 0.05f);  // at most these (the terrain under
                                                                    // the box edge is a little raised)
  const uint32_t roof = count_near(pts, n, 1.5f);
  REQUIRE(roof > 0);
  const uint32_t dropped = remove(pts, n, kClearance);
  CHECK(dropped >= low);
  CHECK(dropped <= high);
  CHECK(count_at_most(pts, n - dropped, kClearance - 0.02f) == 0);
  CHECK(count_near(pts, n - dropped, 1.5f) == roof);  // the box above the clearance is all kept
}

TEST_CASE("a cloud without a ground slab is left whole") {
  std::vector<float> pts = test::box_surface(4.0f, 2.0f, 1.5f, 0.1f);  // no ground: a thin bottom share
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  std::vector<float> before = pts;
  CHECK(remove(pts, n, kClearance) == 0);
  CHECK(pts == before);
  CHECK(remove(pts, n, 0.0f) == 0);  // clearance 0: off
}

TEST_CASE("vehicles without ground keep every point (their hood and sides are not terrain)") {
  for (uint32_t toy = 0; toy < test::kToyModels; ++toy) {
    CAPTURE(toy);
    std::vector<double> pts = test::toy_vehicle_points(toy, 0.05f);
    std::vector<float> seen;  // from the air: no underside
    for (size_t i = 0; i < pts.size(); i += 3)
      if (pts[i + 2] > 0.35)
        for (int a = 0; a < 3; ++a) seen.push_back(static_cast<float>(pts[i + a]));
    const uint32_t n = static_cast<uint32_t>(seen.size() / 3);
    CHECK(remove(seen, n, kClearance) == 0);
  }
}

TEST_CASE("a toy vehicle standing on ground is recognised with the ground removed, and not without") {
  test::ToyDatabase toy;
  REQUIRE(test::make_toy_database(&toy));
  const double t[3] = {500000.0, 4000000.0, 120.0};
  std::vector<double> q = test::toy_query(test::toy_vehicle_points(3, 0.05f), 0.9, t, 0.02, 3);
  std::vector<float> ground = test::plane_grid(6.0f, 0.1f);  // with the view: under max_points, no thinning
  for (size_t i = 0; i < ground.size(); i += 3)
    for (int a = 0; a < 3; ++a) q.push_back(static_cast<double>(ground[i + a]) + t[a]);  // z = model's z = 0
  for (float clearance : {kClearance, 0.0f}) {
    RecognizerConfig cfg;
    cfg.ground_clearance = clearance;
    host::AlignedBytes ws(required_workspace_bytes(cfg));
    Recognizer r;
    REQUIRE(r.init(&toy.db, cfg, ws.data(), ws.size()) == Status::kOk);
    Result res = r.recognize(q.data(), static_cast<uint32_t>(q.size() / 3));
    REQUIRE(res.status == Status::kOk);
    CAPTURE(clearance);
    if (clearance > 0.0f) {
      CHECK(res.stats.extract.points_ground >= ground.size() / 3);
      REQUIRE(res.ranking_count >= 1);
      CHECK(res.ranking[0].model == 3u);
      CHECK(res.confident);
    } else {
      CHECK(res.stats.extract.points_ground == 0);
      CHECK(!res.confident);  // most features are ground no model explains
    }
  }
}

TEST_CASE("a toy vehicle resting on ground tilted by 15 degrees is recognised with the ground removed") {
  test::ToyDatabase toy;
  REQUIRE(test::make_toy_database(&toy));
  test::TerrainShape shape;
  shape.slope_deg = 15.0;
  shape.bump_height = 0.0;
  shape.curb_height = 0.0;
  test::Tile tile;
  test::add_terrain(tile, shape, 5.0, 0.1, 0.02, 9);
  test::add_model(tile, shape, test::toy_vehicle_points(1, 0.05f), 0.0, 0.0, 0.6, 0.35);
  test::remove_occluded_ground(tile);
  const uint32_t n = static_cast<uint32_t>(tile.ground.size());
  uint32_t truth_ground = 0;
  for (uint8_t g : tile.ground) truth_ground += g;
  RecognizerConfig cfg;
  host::AlignedBytes ws(required_workspace_bytes(cfg));
  Recognizer r;
  REQUIRE(r.init(&toy.db, cfg, ws.data(), ws.size()) == Status::kOk);
  Result res = r.recognize(tile.xyz.data(), n);
  REQUIRE(res.status == Status::kOk);
  CHECK(res.stats.extract.points_ground >= 0.97 * truth_ground);
  CHECK(res.stats.extract.points_ground <= truth_ground + 0.05 * (n - truth_ground));
  REQUIRE(res.ranking_count >= 1);
  CHECK(res.ranking[0].model == 1u);
  CHECK(res.confident);
}

TEST_CASE("a cloud that is all level ground is kNotEnoughFeatures or not confident") {
  test::ToyDatabase toy;
  REQUIRE(test::make_toy_database(&toy));
  std::vector<float> ground = test::plane_grid(8.0f, 0.1f);
  for (size_t i = 2; i < ground.size(); i += 3)
    ground[i] += 0.01f * static_cast<float>((i / 3) % 7);  // rough
  RecognizerConfig cfg;
  host::AlignedBytes ws(required_workspace_bytes(cfg));
  Recognizer r;
  REQUIRE(r.init(&toy.db, cfg, ws.data(), ws.size()) == Status::kOk);
  Result res = r.recognize(ground.data(), static_cast<uint32_t>(ground.size() / 3));
  CHECK((res.status == Status::kNotEnoughFeatures || (res.status == Status::kOk && !res.confident)));
}
