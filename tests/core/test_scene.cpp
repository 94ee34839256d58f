// SceneRecognizer (include/spinhash/scene.hpp): a georeferenced tile on an
// 8 degree slope with three toy vehicles (two parked 0.7 m apart, one under
// a tree), a vehicle not in the database, a wall, a building and a crate; each vehicle found and recognised,
// the clutter named and never confident; capacities refused with a status.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "spinhash/database.hpp"
#include "spinhash/scene.hpp"
#include "support/golden_files.hpp"
#include "support/scene_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;
using namespace spinhash::test;

namespace {

struct SceneRun {
  std::vector<uint8_t> raw;
  SceneRecognizer scene;
  Status init = Status::kNotOpen;
  SceneRun(const Database* db, const SceneConfig& cfg) {
    const size_t bytes = required_scene_workspace_bytes(cfg);
    raw.resize(bytes + kBufferAlignment);
    uintptr_t p = reinterpret_cast<uintptr_t>(raw.data());
    void* ws = reinterpret_cast<void*>((p + kBufferAlignment - 1) / kBufferAlignment * kBufferAlignment);
    init = scene.init(db, cfg, ws, bytes);
  }
};

constexpr float kToyClearance = 0.3f;  // m: a toy's box above its origin (toy_database.cpp)
constexpr double kEast = 512345.0, kNorth = 5412345.0, kUp = 312.0;  // UTM-like offsets

void georeference(std::vector<double>& xyz) {
  for (size_t i = 0; i < xyz.size(); i += 3) {
    xyz[i] += kEast;
    xyz[i + 1] += kNorth;
    xyz[i + 2] += kUp;
  }
}

// The scene object whose centre is nearest to (x, y) (local tile coordinates).
const SceneObject* nearest(const SceneResult& r, double x, double y) {
  const SceneObject* best = nullptr;
  double best_d = 1e30;
  for (uint32_t k = 0; k < r.object_count; ++k) {
    const double dx = r.objects[k].center[0] - kEast - x, dy = r.objects[k].center[1] - kNorth - y;
    if (dx * dx + dy * dy < best_d) {
      best_d = dx * dx + dy * dy;
      best = &r.objects[k];
    }
  }
  return best_d < 1.0 ? best : nullptr;
}

}  // namespace

TEST_CASE("scene: vehicles on an 8 degree slope among clutter are found, recognised and placed") {
  const ToyDatabase& toy = shared_toy_database();
  TerrainShape t;
  t.slope_deg = 8.0;
  Tile tile;
  add_terrain(tile, t, 15.0, 0.12, 0.03, 11);
  struct Placed {
    uint32_t model;
    double x, y, yaw;
  };
  // Sedan and pickup side by side (widths 1.8 and 2.0 at y = -6 and -3.4: 0.7 m gap),
  // the truck under a tree, all at 0.1 m spacing without their undersides.
  const Placed cars[3] = {{0, 0.0, -6.0, 0.0}, {1, 0.0, -3.4, 0.0}, {2, 5.0, 6.0, 1.1}};
  for (const Placed& c : cars) add_model(tile, t, toy_vehicle_points(c.model, 0.1f), c.x, c.y, c.yaw, 0.35);
  add_tree(tile, t, 5.5, 5.5, 8.0, 9.5, 6.5, 2.5, 0.15);        // crown 4-9 m over the truck
  add_box(tile, t, -8.0, 8.0, 0.3, 14.0, 0.25, 2.0, 0.0, 0.1);  // wall
  add_box(tile, t, -9.0, -8.0, 0.0, 9.0, 7.0, 5.0, 0.0, 0.2);   // building
  add_box(tile, t, 9.0, -9.0, 0.0, 1.0, 1.0, 0.8, 0.0, 0.1);    // crate
  add_box(tile, t, 10.0, -2.0, 1.57, 7.5, 2.6, 2.0, 0.4, 0.1);  // a vehicle not in the database (bus-like)
  remove_occluded_ground(tile);
  georeference(tile.xyz);

  SceneConfig cfg;
  SceneRun run(&toy.db, cfg);
  REQUIRE(run.init == Status::kOk);
  const SceneResult r = run.scene.recognize(tile.xyz.data(), static_cast<uint32_t>(tile.ground.size()));
  REQUIRE(r.status == Status::kOk);
  CHECK(r.stats.points_in == tile.ground.size());
  CHECK(r.stats.objects_by_kind[static_cast<int>(ObjectKind::kVehicleCandidate)] == 4u);
  for (const Placed& c : cars) {
    CAPTURE(c.model);
    const SceneObject* o = nearest(r, c.x, c.y);
    REQUIRE(o != nullptr);  // REQUIRE does not leave the test here (no exceptions): guard by hand
    if (o == nullptr) continue;
    CHECK(o->kind == ObjectKind::kVehicleCandidate);
    CHECK(o->ranking_count >= 1u);
    if (o->ranking_count == 0) continue;
    CHECK(o->ranking[0].model == c.model);
    CHECK(o->confident);
    // The pose takes the model's origin to the placed origin, georeferenced.
    const double ox = c.x, oy = c.y, oz = terrain_z(t, c.x, c.y);
    CHECK(std::fabs(o->ranking[0].pose.translation[0] - kEast - ox) < 0.3);
    CHECK(std::fabs(o->ranking[0].pose.translation[1] - kNorth - oy) < 0.3);
    CHECK(std::fabs(o->ranking[0].pose.translation[2] - kUp - oz) < 0.3);
    // The toys have no wheels: their boxes start kToyClearance above the
    // origin, which rests on the terrain.
    CHECK(o->ground_gap == doctest::Approx(kToyClearance).scale(0.0).epsilon(0.25));
  }
  uint32_t confident = 0;
  for (uint32_t k = 0; k < r.object_count; ++k) confident += r.objects[k].confident ? 1u : 0u;
  CHECK(confident == 3u);  // nothing else, the unknown vehicle included
  const SceneObject* bus = nearest(r, 10.0, -2.0);
  REQUIRE(bus != nullptr);
  if (bus) CHECK(bus->kind == ObjectKind::kVehicleCandidate);
  const SceneObject* wall = nearest(r, -8.0, 8.0);
  REQUIRE(wall != nullptr);
  if (wall) CHECK(wall->kind == ObjectKind::kNotVehicleShaped);
  // The building is two objects on one footprint: its walls (low layer, too
  // large) and its roof (high layer, floating above the terrain).
  uint32_t building_parts = 0, building_too_large = 0;
  for (uint32_t k = 0; k < r.object_count; ++k) {
    const SceneObject& o = r.objects[k];
    if (std::hypot(o.center[0] - kEast + 9.0, o.center[1] - kNorth + 8.0) > 1.0) continue;
    ++building_parts;
    building_too_large += o.kind == ObjectKind::kTooLarge ? 1u : 0u;
    CHECK(o.kind != ObjectKind::kVehicleCandidate);
  }
  CHECK(building_parts >= 1u);
  CHECK(building_too_large >= 1u);
  const SceneObject* crate = nearest(r, 9.0, -9.0);
  REQUIRE(crate != nullptr);
  if (crate) CHECK(crate->kind == ObjectKind::kTooSmall);
}

TEST_CASE("scene: a model sunk into the terrain under its pose is not confident") {
  // The toy sedan 0.5 m down into a 5 degree slope, its buried part unseen:
  // recognised and placed, but its model's bottom lies 0.2 m below the
  // terrain, as a taller look-alike's does when posed to fit a scan's roof.
  const ToyDatabase& toy = shared_toy_database();
  TerrainShape t;
  t.slope_deg = 5.0;
  Tile tile;
  add_terrain(tile, t, 10.0, 0.12, 0.03, 5);
  constexpr double kSink = 0.5, kUnseenBelow = 0.35;
  const int car = add_model(tile, t, toy_vehicle_points(0, 0.1f), 0.0, 0.0, 0.4, kSink + kUnseenBelow);
  for (size_t i = 0; i < tile.object.size(); ++i)
    if (tile.object[i] == car) tile.xyz[3 * i + 2] -= kSink;
  remove_occluded_ground(tile);
  georeference(tile.xyz);
  for (float sink : {SceneConfig{}.max_ground_sink, 1.0f}) {
    CAPTURE(sink);
    SceneConfig cfg;
    cfg.max_ground_sink = sink;
    SceneRun run(&toy.db, cfg);
    REQUIRE(run.init == Status::kOk);
    const SceneResult r = run.scene.recognize(tile.xyz.data(), static_cast<uint32_t>(tile.ground.size()));
    REQUIRE(r.status == Status::kOk);
    const SceneObject* o = nearest(r, 0.0, 0.0);
    REQUIRE(o != nullptr);
    if (o == nullptr || o->ranking_count == 0) continue;
    CHECK(o->ranking[0].model == 0u);
    CHECK(o->ground_gap == doctest::Approx(kToyClearance - kSink).scale(0.0).epsilon(0.25));
    CHECK(o->confident == (sink > 0.5f));
  }
}

TEST_CASE(
    "scene: a window over max_tile_points or over its grid is kWindowOverflow, counted, nothing answered") {
  host::AlignedBytes blob = golden_blob(true);
  Database db;
  REQUIRE(Database::open(blob.data(), blob.size(), &db) == Status::kOk);
  TerrainShape t;
  Tile tile;
  add_terrain(tile, t, 10.0, 0.25, 0.02, 1);
  const uint32_t n = static_cast<uint32_t>(tile.ground.size());
  SceneConfig cfg;
  cfg.recognizer.max_points = 4096;
  cfg.object_margin = cfg.window_margin;  // every window gathers the whole 20 m tile
  cfg.max_tile_points = n - 1;
  {
    SceneRun run(&db, cfg);
    REQUIRE(run.init == Status::kOk);
    const SceneResult r = run.scene.recognize(tile.xyz.data(), n);
    CHECK(r.status == Status::kWindowOverflow);  // each window of the lattice sees all n points
    CHECK(r.stats.windows >= 1u);
    CHECK(r.stats.windows_overflowed == r.stats.windows);
    CHECK(r.object_count == 0u);
  }
  cfg.max_tile_points = n;
  cfg.max_terrain_cells = 1000;  // 20 x 20 m at 0.5 m needs 41 x 41 (the tile API keeps the config's grids)
  {
    SceneRun run(&db, cfg);
    REQUIRE(run.init == Status::kOk);
    const SceneResult r = run.scene.recognize(tile.xyz.data(), n);
    CHECK(r.status == Status::kWindowOverflow);
    CHECK(r.stats.windows_overflowed == r.stats.windows);
    std::vector<double> nan_only = {NAN, 1.0, 2.0};
    CHECK(run.scene.recognize(nan_only.data(), 1).status == Status::kEmptyCloud);
    CHECK(run.scene.recognize(nullptr, 3).status == Status::kInvalidArgument);
  }
  cfg.max_terrain_cells = 2000;  // 41 x 41 cells (and the snap) fit
  {
    SceneRun run(&db, cfg);
    REQUIRE(run.init == Status::kOk);
    const SceneResult r = run.scene.recognize(tile.xyz.data(), n);
    CHECK(r.status == Status::kOk);
    CHECK(r.object_count == 0u);  // bare ground: no objects
    // Every point ground, counted once though the windows overlap.
    CHECK(r.stats.windows > 1u);
    CHECK(r.stats.points_ground == n);
  }
  SceneRecognizer never;
  CHECK(never.recognize(tile.xyz.data(), n).status == Status::kNotOpen);
  SceneConfig bad;
  bad.top_n = 0;
  CHECK(required_scene_workspace_bytes(bad) == 0u);
}

TEST_CASE(
    "scene: a window's recognitions share window_max_work; once it is spent the rest are not recognised") {
  const ToyDatabase& toy = shared_toy_database();
  TerrainShape t;
  Tile tile;
  add_terrain(tile, t, 12.0, 0.12, 0.03, 5);
  // Three toys side by side, 0.7-1 m apart: one window's candidates.
  const double ys[3] = {-3.0, -0.4, 2.4};
  for (uint32_t m = 0; m < 3; ++m) add_model(tile, t, toy_vehicle_points(m, 0.1f), 0.0, ys[m], 0.0, 0.35);
  remove_occluded_ground(tile);
  georeference(tile.xyz);
  const uint32_t n = static_cast<uint32_t>(tile.ground.size());
  const auto candidates = [](const SceneResult& r) {
    uint32_t c = 0;
    for (uint32_t k = 0; k < r.object_count; ++k)
      c += r.objects[k].kind == ObjectKind::kVehicleCandidate ||
           r.objects[k].status == Status::kWorkCapReached;
    return c;
  };

  SceneConfig cfg;
  cfg.window_core = 64.0f;  // the whole tile in one window's core
  SceneRun free_run(&toy.db, cfg);
  REQUIRE(free_run.init == Status::kOk);
  const SceneResult free = free_run.scene.recognize(tile.xyz.data(), n);
  REQUIRE(free.status == Status::kOk);
  REQUIRE(free.stats.objects_by_kind[static_cast<int>(ObjectKind::kVehicleCandidate)] == 3u);
  uint64_t work = 0;
  std::vector<uint32_t> models;
  for (uint32_t k = 0; k < free.object_count; ++k) {
    const SceneObject& o = free.objects[k];
    if (o.kind != ObjectKind::kVehicleCandidate) continue;
    CHECK(o.status == Status::kOk);
    work += o.stats.cascade.work;
    models.push_back(o.ranking_count > 0 ? o.ranking[0].model : ~0u);
  }
  CHECK(free.stats.recognition_work == work);
  CHECK(free.stats.objects_out_of_work == 0u);

  // A budget the three fit in answers as without one.
  cfg.window_max_work = work + 1u;
  SceneRun fits_run(&toy.db, cfg);
  REQUIRE(fits_run.init == Status::kOk);
  const SceneResult fits = fits_run.scene.recognize(tile.xyz.data(), n);
  CHECK(fits.stats.objects_out_of_work == 0u);
  CHECK(fits.stats.recognition_work == work);
  std::vector<uint32_t> fit_models;
  for (uint32_t k = 0; k < fits.object_count; ++k)
    if (fits.objects[k].kind == ObjectKind::kVehicleCandidate)
      fit_models.push_back(fits.objects[k].ranking_count > 0 ? fits.objects[k].ranking[0].model : ~0u);
  CHECK(fit_models == models);

  // A budget of one unit: the first candidate's recognition is capped at
  // once (charged its first extraction, which it skips), the other two are not run.
  cfg.window_max_work = 1u;
  SceneRun tight_run(&toy.db, cfg);
  REQUIRE(tight_run.init == Status::kOk);
  const SceneResult tight = tight_run.scene.recognize(tile.xyz.data(), n);
  CHECK(tight.status == Status::kOk);
  CHECK(candidates(tight) == 3u);
  CHECK(tight.stats.objects_out_of_work == 2u);
  CHECK(tight.stats.recognition_work < work);
  uint32_t capped = 0, unrecognised = 0;
  for (uint32_t k = 0; k < tight.object_count; ++k) {
    const SceneObject& o = tight.objects[k];
    if (o.status != Status::kWorkCapReached) continue;
    CHECK_FALSE(o.confident);
    CHECK(o.level == AnswerLevel::kNone);
    if (o.kind == ObjectKind::kUnknown && o.ranking_count == 0u && o.stats.cascade.work == 0u)
      ++unrecognised;
    else
      ++capped;
  }
  CHECK(capped == 1u);
  CHECK(unrecognised == 2u);
}
