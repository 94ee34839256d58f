// Objects of a tile (scene/segment.hpp): cars 0.6 m apart part, a crown over
// a car stays apart from it, extents along the principal axes, and the cap
// on objects reported by status.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "geometry/terrain.hpp"
#include "scene/segment.hpp"
#include "support/scene_fixtures.hpp"
#include "support/stream_terrain.hpp"

using namespace spinhash;
using namespace spinhash::test;

namespace {

struct Segmented {
  Status status = Status::kNotOpen;
  std::vector<ObjectShape> objects;
  std::vector<uint32_t> label;
  SegmentStats stats;
};

Segmented segment(const Tile& tile, uint32_t max_objects = 64) {
  const uint32_t n = static_cast<uint32_t>(tile.ground.size());
  const StreamTerrain terrain = stream_terrain(tile.xyz, TerrainParams{});
  REQUIRE(terrain.status == Status::kOk);
  const uint32_t cells = 1u << 16;
  Arena counter;
  SegmentGrid sg;
  sg.carve(counter, cells);
  std::vector<uint8_t> ws(counter.used() + 64);
  Arena arena(ws.data(), ws.size());
  sg.carve(arena, cells);
  Segmented s;
  SegmentParams p;
  p.max_objects = max_objects;
  s.objects.resize(max_objects);
  s.label.resize(n);
  s.status = segment_objects(terrain.local.data(), terrain.height.data(), terrain.ground.data(), n, p, sg,
                             s.objects.data(), s.label.data(), &s.stats);
  s.objects.resize(s.stats.objects);
  return s;
}

// The object holding most of the points that fixture object `id` made, and
// the share of that fixture object's points it holds.
uint32_t object_of(const Tile& tile, const Segmented& s, int id, double* share) {
  std::vector<uint32_t> votes(s.objects.size() + 1, 0);
  uint32_t total = 0;
  for (size_t i = 0; i < tile.object.size(); ++i)
    if (tile.object[i] == id) {
      ++total;
      ++votes[s.label[i] == kNoObject ? s.objects.size() : s.label[i]];
    }
  uint32_t best = 0;
  REQUIRE(!s.objects.empty());  // callers index s.objects with the answer
  if (s.objects.empty()) return 0;
  for (uint32_t k = 1; k < s.objects.size(); ++k) best = votes[k] > votes[best] ? k : best;
  *share = total ? static_cast<double>(votes[best]) / total : 0.0;
  return best;
}

}  // namespace

TEST_CASE("segmentation: two cars 0.6 m apart on an 8 degree slope are two objects of the right size") {
  TerrainShape t;
  t.slope_deg = 8.0;
  Tile tile;
  add_terrain(tile, t, 10.0, 0.15, 0.03, 3);
  add_box(tile, t, 0.0, -1.2, 0.0, 4.5, 1.8, 1.2, 0.3, 0.1);  // y from -2.1 to -0.3
  add_box(tile, t, 0.0, 1.2, 0.0, 4.5, 1.8, 1.2, 0.3, 0.1);   // gap 0.6 m
  remove_occluded_ground(tile);
  const Segmented s = segment(tile);
  REQUIRE(s.status == Status::kOk);
  REQUIRE(!s.objects.empty());
  if (s.objects.empty()) return;  // REQUIRE does not leave the test (no exceptions)
  double share0 = 0, share1 = 0;
  const uint32_t a = object_of(tile, s, 0, &share0), b = object_of(tile, s, 1, &share1);
  CHECK(a != b);
  CHECK(share0 >= 0.95);
  CHECK(share1 >= 0.95);
  for (uint32_t k : {a, b}) {
    CHECK(s.objects[k].length() == doctest::Approx(4.5).epsilon(0.08));
    CHECK(s.objects[k].width() == doctest::Approx(1.8).epsilon(0.1));
    CHECK(s.objects[k].hmax == doctest::Approx(1.5).epsilon(0.1));
    CHECK(std::fabs(s.objects[k].ay) < 0.05);  // length along x
  }
}

TEST_CASE("segmentation: a tree crown over a car stays apart from the car") {
  TerrainShape t;
  t.slope_deg = 5.0;
  Tile tile;
  add_terrain(tile, t, 10.0, 0.15, 0.03, 4);
  add_box(tile, t, 0.0, 0.0, 0.7, 4.5, 1.8, 1.2, 0.3, 0.1);
  add_tree(tile, t, 0.5, 0.5, 0.0, 3.0, 6.4, 2.2, 0.15);  // crown from 4.2 to 8.6 m, trunk 2 m beside the car
  remove_occluded_ground(tile);
  const Segmented s = segment(tile);
  REQUIRE(s.status == Status::kOk);
  REQUIRE(!s.objects.empty());
  if (s.objects.empty()) return;  // REQUIRE does not leave the test (no exceptions)
  double car_share = 0;
  const uint32_t car = object_of(tile, s, 0, &car_share);
  CHECK(car_share >= 0.95);
  uint32_t tree_in_car = 0;
  for (size_t i = 0; i < tile.object.size(); ++i) tree_in_car += tile.object[i] == 1 && s.label[i] == car;
  CHECK(tree_in_car == 0u);
  CHECK(s.objects[car].hmax < 1.7f);
  CHECK(s.objects[car].length() == doctest::Approx(4.5).epsilon(0.08));
  bool crown_high = false;
  for (const ObjectShape& o : s.objects)
    crown_high = crown_high || (o.high_layer && o.hmin > 3.5f && o.hmax > 8.0f);
  CHECK(crown_high);
}

TEST_CASE("segmentation: a low crown (3.2 m, below the layer split) over a car stays apart from it") {
  TerrainShape t;
  t.slope_deg = 10.0;
  Tile tile;
  add_terrain(tile, t, 10.0, 0.15, 0.03, 6);
  add_box(tile, t, 0.0, 0.0, 0.3, 4.5, 1.8, 1.2, 0.3, 0.1);
  add_tree(tile, t, 0.0, 0.0, 0.0, 3.0, 5.2, 2.0, 0.15);  // crown 3.2-7.2 m right over the car
  remove_occluded_ground(tile);
  const Segmented s = segment(tile);
  REQUIRE(s.status == Status::kOk);
  REQUIRE(!s.objects.empty());
  if (s.objects.empty()) return;
  double car_share = 0;
  const uint32_t car = object_of(tile, s, 0, &car_share);
  CHECK(car_share >= 0.95);
  uint32_t tree_in_car = 0;
  for (size_t i = 0; i < tile.object.size(); ++i) tree_in_car += tile.object[i] == 1 && s.label[i] == car;
  CHECK(tree_in_car == 0u);
  CHECK(s.objects[car].hmax < 1.7f);
}

TEST_CASE("segmentation: more objects than the cap is kTooManyObjects, the first ones kept") {
  TerrainShape t;
  Tile tile;
  add_terrain(tile, t, 8.0, 0.2, 0.02, 5);
  add_box(tile, t, -3.0, 0.0, 0.0, 4.0, 1.8, 1.4, 0.3, 0.1);
  add_box(tile, t, 3.0, 0.0, 0.0, 4.0, 1.8, 1.4, 0.3, 0.1);
  remove_occluded_ground(tile);
  const Segmented all = segment(tile);
  CHECK(all.status == Status::kOk);
  CHECK(all.stats.objects == 2u);
  const Segmented capped = segment(tile, 1);
  CHECK(capped.status == Status::kTooManyObjects);
  CHECK(capped.stats.objects == 1u);
  CHECK(capped.stats.dropped == 1u);
  if (!capped.objects.empty() && !all.objects.empty())
    CHECK(capped.objects[0].points == all.objects[0].points);
}
