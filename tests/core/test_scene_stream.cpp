// SceneStream (include/spinhash/scene_stream.hpp), on a 160 m strip of a
// flight line with toy vehicles placed on and near the window cores' edges:
// each vehicle reported once, named as the whole strip names it; the same
// answers for any chunking; bad input counted, never a crash; points out of
// order said so; work that follows the points over kilometres of nothing.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/scene_window.hpp"
#include "spinhash/database.hpp"
#include "spinhash/scene.hpp"
#include "spinhash/scene_stream.hpp"
#include "support/scene_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;
using namespace spinhash::test;

namespace {

constexpr double kEast = 512345.0, kNorth = 5412345.0, kUp = 312.0;  // UTM-like offsets

struct Placed {
  uint32_t model;
  double x, y, yaw;
};
// Along the strip (north, +y): row edges of the 32 m cores lie at y = 0, 32,
// 64, 96 and 128 from the origin; vehicles straddle several of them.
constexpr Placed kCars[] = {{0, 0.0, 10.0, 0.3}, {1, -3.0, 31.8, 1.57}, {2, 3.0, 64.2, 0.0},
                            {3, 0.0, 95.9, 1.2}, {4, -4.0, 128.0, 0.0}, {5, 4.0, 140.0, 2.0}};
constexpr uint32_t kCarCount = sizeof(kCars) / sizeof(kCars[0]);

// The strip's points, georeferenced, sorted along track (scan order).
std::vector<double> strip_points() {
  TerrainShape t;
  Tile tile;
  add_terrain_rect(tile, t, -10.0, 10.0, -5.0, 155.0, 0.25, 0.02, 3);
  for (const Placed& c : kCars) add_model(tile, t, toy_vehicle_points(c.model, 0.1f), c.x, c.y, c.yaw, 0.35);
  remove_occluded_ground(tile);
  const double georef[3] = {kEast, kNorth, kUp};
  return in_scan_order(tile, 1, georef);
}

struct Reported {
  ObjectKind kind;
  double center[3];
  uint32_t points;
  int64_t model;  // -1 without a ranking
  float score;
  bool confident;
};

void collect(void* context, const SceneObject& o, int64_t, uint32_t) {
  Reported r{o.kind,
             {o.center[0], o.center[1], o.center[2]},
             o.points,
             o.ranking_count ? static_cast<int64_t>(o.ranking[0].model) : -1,
             o.ranking_count ? o.ranking[0].score : 0.0f,
             o.confident};
  static_cast<std::vector<Reported>*>(context)->push_back(r);
}

StreamConfig strip_config() {
  StreamConfig c;
  c.origin_given = true;
  c.origin[0] = kEast;
  c.origin[1] = kNorth;
  c.origin[2] = kUp;
  c.heading_deg = 90.0f;  // along +y
  c.swath_min = c.own_min = -64.0f;
  c.swath_max = c.own_max = 64.0f;
  c.max_lag = 4.0f;
  c.scene.window_core = 64.0f;  // the strip's vehicles sit on this lattice's core edges
  c.scene.max_tile_points = 400000;
  c.max_buffered_points = 400000;
  return c;
}

struct StreamRun {
  std::vector<uint8_t> raw;
  SceneStream stream;
  std::vector<Reported> objects;
  Status init = Status::kNotOpen;
  StreamRun(const Database* db, const StreamConfig& cfg) {
    const size_t bytes = required_stream_workspace_bytes(cfg);
    raw.resize(bytes + kBufferAlignment);
    const uintptr_t p = reinterpret_cast<uintptr_t>(raw.data());
    void* ws = reinterpret_cast<void*>((p + kBufferAlignment - 1) / kBufferAlignment * kBufferAlignment);
    init = stream.init(db, cfg, ws, bytes, collect, &objects);
  }
  // Pushes xyz in chunks of `chunk` points, then flushes; the worst status.
  Status feed(const std::vector<double>& xyz, size_t chunk) {
    Status worst = Status::kOk;
    const size_t n = xyz.size() / 3;
    for (size_t i = 0; i < n; i += chunk) {
      const uint32_t m = static_cast<uint32_t>(std::min(chunk, n - i));
      const Status s = stream.push(xyz.data() + 3 * i, m);
      if (s != Status::kOk) worst = s;
    }
    const Status f = stream.flush();
    return f != Status::kOk ? f : worst;
  }
};

const Reported* vehicle_at(const std::vector<Reported>& objects, const Placed& c, int* count) {
  const Reported* found = nullptr;
  *count = 0;
  for (const Reported& o : objects) {
    const double dx = o.center[0] - kEast - c.x, dy = o.center[1] - kNorth - c.y;
    if (dx * dx + dy * dy > 1.5 * 1.5) continue;
    ++*count;
    found = &o;
  }
  return found;
}

}  // namespace

TEST_CASE("stream: every vehicle of a strip is reported once, named as the whole strip names it") {
  const ToyDatabase& toy = shared_toy_database();
  const std::vector<double> xyz = strip_points();
  StreamRun run(&toy.db, strip_config());
  REQUIRE(run.init == Status::kOk);
  CHECK(run.feed(xyz, xyz.size() / 3) == Status::kOk);
  const StreamStats& st = run.stream.stats();
  CHECK(st.points_pushed == xyz.size() / 3);
  CHECK(st.windows >= 5u);           // rows of 32 m over 160 m
  CHECK(st.objects_not_owned > 0u);  // neighbours saw the vehicles near their edges too
  CHECK(st.points_late + st.points_glitch + st.points_outside + st.points_overflow == 0u);
  // Each point is counted once, by the window that owns it, though the
  // windows' margins overlap.
  CHECK(st.scene.points_in == st.points_pushed);
  CHECK(st.scene.points_ground + st.scene.points_in_objects + st.scene.points_fragments ==
        st.scene.points_in);
  CHECK(st.scene.points_in_objects > 0u);

  // The whole strip through the tile API (the stream's path over a tile in
  // memory: its own frame, bands and rows) for reference.
  SceneConfig whole;
  whole.max_tile_points = 400000;
  std::vector<uint8_t> raw(required_scene_workspace_bytes(whole) + kBufferAlignment);
  const uintptr_t p = reinterpret_cast<uintptr_t>(raw.data());
  void* ws = reinterpret_cast<void*>((p + kBufferAlignment - 1) / kBufferAlignment * kBufferAlignment);
  SceneRecognizer scene;
  REQUIRE(scene.init(&toy.db, whole, ws, required_scene_workspace_bytes(whole)) == Status::kOk);
  const SceneResult tile = scene.recognize(xyz.data(), static_cast<uint32_t>(xyz.size() / 3));
  REQUIRE(tile.status == Status::kOk);
  CHECK(tile.stats.windows > 1u);
  CHECK(tile.points_lost == 0u);
  CHECK(tile.stats.points_in == xyz.size() / 3);
  CHECK(tile.stats.points_ground + tile.stats.points_in_objects + tile.stats.points_fragments ==
        xyz.size() / 3);
  std::vector<Reported> tile_objects;
  for (uint32_t k = 0; k < tile.object_count; ++k) collect(&tile_objects, tile.objects[k], 0, 0);

  for (const Placed& c : kCars) {
    CAPTURE(c.model);
    CAPTURE(c.y);
    int in_stream = 0, in_tile = 0;
    const Reported* s = vehicle_at(run.objects, c, &in_stream);
    const Reported* t = vehicle_at(tile_objects, c, &in_tile);
    CHECK(in_stream == 1);
    CHECK(in_tile == 1);
    REQUIRE(s != nullptr);
    REQUIRE(t != nullptr);
    CHECK(s->kind == ObjectKind::kVehicleCandidate);
    CHECK(s->model == static_cast<int64_t>(c.model));
    CHECK(s->model == t->model);
    // The margins see the vehicle whole; its lowest points may fall on the
    // ground side in one lattice of grid cells and not in the other.
    CHECK(std::abs(static_cast<int>(s->points) - static_cast<int>(t->points)) <= 0.03 * t->points);
  }
}

TEST_CASE("stream: windows that share a row's terrain grid name every vehicle as windows with a grid each") {
  const ToyDatabase& toy = shared_toy_database();
  const std::vector<double> xyz = strip_points();
  StreamConfig own_grid = strip_config();
  own_grid.scene.max_terrain_cells = 100000;  // one 144 m window's 290 x 290 cells, not two side by side
  REQUIRE(strip_columns(strip_config().scene) == 2u);
  REQUIRE(strip_columns(own_grid.scene) == 1u);
  StreamRun shared(&toy.db, strip_config()), separate(&toy.db, own_grid);
  REQUIRE(shared.init == Status::kOk);
  REQUIRE(separate.init == Status::kOk);
  CHECK(shared.feed(xyz, 4096 / 24) == Status::kOk);
  CHECK(separate.feed(xyz, 4096 / 24) == Status::kOk);
  CHECK(shared.stream.stats().windows == separate.stream.stats().windows);
  // One grid per row instead of one per window: fewer cells filled in all.
  CHECK(shared.stream.stats().scene.terrain_cells < separate.stream.stats().scene.terrain_cells);
  for (const Placed& c : kCars) {
    CAPTURE(c.model);
    CAPTURE(c.y);
    int in_shared = 0, in_separate = 0;
    const Reported* a = vehicle_at(shared.objects, c, &in_shared);
    const Reported* b = vehicle_at(separate.objects, c, &in_separate);
    CHECK(in_shared == 1);
    CHECK(in_separate == 1);
    REQUIRE(a != nullptr);
    REQUIRE(b != nullptr);
    CHECK(a->model == static_cast<int64_t>(c.model));
    CHECK(a->model == b->model);
    CHECK(a->confident == b->confident);
    CHECK(std::abs(static_cast<int>(a->points) - static_cast<int>(b->points)) <= 0.03 * b->points);
  }
}

TEST_CASE("stream: the same answers whole, in 4 kB chunks and one point at a time") {
  const ToyDatabase& toy = shared_toy_database();
  const std::vector<double> xyz = strip_points();
  StreamRun whole(&toy.db, strip_config()), chunked(&toy.db, strip_config()), single(&toy.db, strip_config());
  REQUIRE(whole.init == Status::kOk);
  CHECK(whole.feed(xyz, xyz.size() / 3) == Status::kOk);
  CHECK(chunked.feed(xyz, 4096 / 24) == Status::kOk);
  CHECK(single.feed(xyz, 1) == Status::kOk);
  REQUIRE(whole.objects.size() >= kCarCount);
  for (const StreamRun* other : {&chunked, &single}) {
    REQUIRE(other->objects.size() == whole.objects.size());
    for (size_t k = 0; k < whole.objects.size(); ++k) {
      const Reported &a = whole.objects[k], &b = other->objects[k];
      CHECK(a.kind == b.kind);
      CHECK(a.points == b.points);
      CHECK(a.model == b.model);
      CHECK(a.score == b.score);
      CHECK(a.confident == b.confident);
      for (int i = 0; i < 3; ++i) CHECK(a.center[i] == b.center[i]);
    }
  }
}

TEST_CASE("stream: NaN, a GNSS glitch, late points and a push after the flush are counted, answers kept") {
  const ToyDatabase& toy = shared_toy_database();
  std::vector<double> xyz = strip_points();
  StreamRun clean(&toy.db, strip_config());
  REQUIRE(clean.feed(xyz, 1000) == Status::kOk);

  // Inserted two thirds of the way (y ~ 100 m): a NaN, a point 10 km across
  // track, a jump 10 km ahead (not confirmed), and a point 150 m behind the
  // line, where every window that sees it has run.
  const size_t at = 3 * (2 * xyz.size() / 9);
  const double y = xyz[at + 1];
  const std::vector<double> bad = {NAN,   kNorth,      kUp, kEast + 10000.0, y,         kUp,
                                   kEast, y + 10000.0, kUp, kEast,           y - 150.0, kUp};
  xyz.insert(xyz.begin() + static_cast<std::ptrdiff_t>(at), bad.begin(), bad.end());
  StreamRun dirty(&toy.db, strip_config());
  CHECK(dirty.feed(xyz, 1000) == Status::kPointsLate);  // the late point: dropped, and said so
  const StreamStats& st = dirty.stream.stats();
  CHECK(st.scene.points_nonfinite == 1u);
  CHECK(st.points_outside == 1u);
  CHECK(st.points_glitch == 1u);
  CHECK(st.points_late == 1u);
  REQUIRE(dirty.objects.size() == clean.objects.size());
  for (size_t k = 0; k < clean.objects.size(); ++k) {
    CHECK(dirty.objects[k].model == clean.objects[k].model);
    CHECK(dirty.objects[k].points == clean.objects[k].points);
  }

  CHECK(dirty.stream.push(xyz.data(), 10) == Status::kStreamFlushed);
  CHECK(dirty.stream.stats().points_after_flush == 10u);
  dirty.stream.reset();
  dirty.objects.clear();
  CHECK(dirty.stream.stats().points_pushed == 0u);
  CHECK(dirty.feed(xyz, 50000) == Status::kPointsLate);
  CHECK(dirty.objects.size() == clean.objects.size());
}

TEST_CASE("stream: a full buffer or window is kWindowOverflow, counted; a confirmed gap is a gap") {
  const ToyDatabase& toy = shared_toy_database();
  const std::vector<double> xyz = strip_points();
  StreamConfig small = strip_config();
  small.max_buffered_points = 20000;  // less than 112 m of strip
  StreamRun run(&toy.db, small);
  REQUIRE(run.init == Status::kOk);
  CHECK(run.feed(xyz, 4096) == Status::kWindowOverflow);
  CHECK(run.stream.stats().points_overflow > 0u);

  StreamConfig narrow = strip_config();
  narrow.scene.max_tile_points = 10000;  // a window sees more
  StreamRun run2(&toy.db, narrow);
  REQUIRE(run2.init == Status::kOk);
  CHECK(run2.feed(xyz, 4096) == Status::kWindowOverflow);
  CHECK(run2.stream.stats().windows_overflowed > 0u);
  CHECK(run2.stream.stats().points_in_overflowed > 0u);

  // The strip's second half 2 km further on: a gap in the data, confirmed
  // by the points after it, not a glitch.
  std::vector<double> gap = xyz;
  for (size_t i = gap.size() / 2 / 3 * 3; i < gap.size(); i += 3) gap[i + 1] += 2000.0;
  StreamConfig jumpy = strip_config();
  jumpy.max_jump = 500.0f;
  StreamRun run3(&toy.db, jumpy);
  CHECK(run3.feed(gap, 4096) == Status::kOk);
  CHECK(run3.stream.stats().points_glitch == 0u);
  CHECK(run3.stream.stats().points_late == 0u);
}

TEST_CASE("stream: invalid configs are refused; the workspace does not depend on the line") {
  StreamConfig c = strip_config();
  CHECK(stream_config_valid(c));
  const size_t bytes = required_stream_workspace_bytes(c);
  CHECK(bytes > 0u);
  c.own_max = 100.0f;  // beyond the swath
  CHECK(!stream_config_valid(c));
  c = strip_config();
  c.scene.window_core = 32.1f;  // not a multiple of the grid cells
  CHECK(!stream_config_valid(c));
  c = strip_config();
  c.max_lag = NAN;
  CHECK(required_stream_workspace_bytes(c) == 0u);
  SceneStream never;
  CHECK(never.push(nullptr, 0) == Status::kNotOpen);
  CHECK(never.flush() == Status::kNotOpen);
  CHECK(never.stats().points_pushed == 0u);
}

TEST_CASE("stream: points pushed out of order are dropped with kPointsLate, never silently") {
  const ToyDatabase& toy = shared_toy_database();
  const std::vector<double> xyz = strip_points();
  const size_t n = xyz.size() / 3;
  // The strip's second half pushed first, then its first half: the first
  // half lies more than max_lag behind the furthest point pushed.
  std::vector<double> swapped(xyz.begin() + static_cast<std::ptrdiff_t>(3 * (n / 2)), xyz.end());
  swapped.insert(swapped.end(), xyz.begin(), xyz.begin() + static_cast<std::ptrdiff_t>(3 * (n / 2)));
  StreamRun run(&toy.db, strip_config());
  REQUIRE(run.init == Status::kOk);
  const uint32_t second = static_cast<uint32_t>(n - n / 2);
  CHECK(run.stream.push(swapped.data(), second) == Status::kOk);
  CHECK(run.stream.push(swapped.data() + 3 * static_cast<size_t>(second), static_cast<uint32_t>(n / 2)) ==
        Status::kPointsLate);
  CHECK(run.stream.flush() == Status::kOk);
  CHECK(run.stream.stats().points_late > 0u);
  CHECK(run.stream.stats().points_late <= n / 2);
}

TEST_CASE(
    "stream: work follows the points: two patches 5 km apart (78 rows of cores) run their windows, not the "
    "rows between") {
  const ToyDatabase& toy = shared_toy_database();
  std::vector<double> xyz = strip_points();
  const size_t n = xyz.size() / 3;
  std::vector<double> both = xyz;
  for (size_t i = 0; i < n; ++i)
    both.insert(both.end(), {xyz[3 * i], xyz[3 * i + 1] + 4992.0, xyz[3 * i + 2]});
  StreamConfig c = strip_config();
  c.max_jump = 10000.0f;  // the gap is data, not a glitch
  StreamRun one(&toy.db, c), two(&toy.db, c);
  REQUIRE(one.feed(xyz, 4096) == Status::kOk);
  REQUIRE(two.feed(both, 4096) == Status::kOk);
  const StreamStats &a = one.stream.stats(), &b = two.stream.stats();
  CHECK(b.windows == 2u * a.windows);
  CHECK(b.scene.terrain_cells == 2u * a.scene.terrain_cells);
  CHECK(b.points_late + b.points_glitch + b.points_outside == 0u);
  CHECK(two.objects.size() == 2u * one.objects.size());
}
