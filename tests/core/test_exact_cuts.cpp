// The exact cuts give what the plain code gives, bit for bit:
// the radius search that skips cells beyond the radius visits the points a
// brute-force scan of its cells would, in the same order; normals over
// gathered neighbourhoods equal the point-by-point ones (also when the
// scratch overflows); BRAN's model groups list each model's candidates in
// list order. The stream's buffer decides on the 1 mm steps what it would
// decide on the coordinates: first_step_from's bound against from_steps,
// lattice_steps against llround.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "geometry/normals.hpp"
#include "recognize/model_groups.hpp"
#include "scene/window_lattice.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/grid_fixture.hpp"
#include "util/rng.hpp"

using namespace spinhash;

namespace {

// A noisy sphere and plane: cells of every occupancy.
std::vector<float> cloud() {
  std::vector<float> pts = test::fibonacci_sphere(2500, 1.2f, 0.3f, -0.2f, 0.9f);
  const std::vector<float> plane = test::plane_grid(3.0f, 0.07f);
  pts.insert(pts.end(), plane.begin(), plane.end());
  Pcg32 rng(29);
  for (float& v : pts) v += 0.01f * (rng.uniform() - 0.5f);
  return pts;
}

// The indices for_each_within passes, in order.
std::vector<uint32_t> visited(const CellGrid& grid, const float* q, float radius) {
  std::vector<uint32_t> out;
  grid.for_each_within(q, radius, [&](uint32_t j) { out.push_back(j); });
  return out;
}

// The same from every cell within the reach, none skipped (the plain search):
// the points within the radius, cell offset by cell offset (dz, then dy, then
// dx), each cell's in the grid's order.
std::vector<uint32_t> visited_unculled(const CellGrid& grid, const float* pts, const float* q, float radius) {
  const float cell = grid.cell_size();
  const int32_t reach = static_cast<int32_t>(std::ceil(radius / cell));
  const int32_t side = 2 * reach + 1;
  const float r2 = radius * radius;
  auto c = [&](float v) { return static_cast<int32_t>(std::floor(v / cell)); };
  std::vector<std::vector<uint32_t>> by_offset(static_cast<size_t>(side * side * side));
  for (uint32_t k = 0; k < grid.cell_count(); ++k)
    for (uint32_t m = 0; m < grid.cell_size_of(k); ++m) {
      const uint32_t j = grid.order()[grid.cell_first(k) + m];
      const float* p = pts + 3u * j;
      const int32_t dx = c(p[0]) - c(q[0]), dy = c(p[1]) - c(q[1]), dz = c(p[2]) - c(q[2]);
      if (std::abs(dx) > reach || std::abs(dy) > reach || std::abs(dz) > reach) continue;
      const float ex = p[0] - q[0], ey = p[1] - q[1], ez = p[2] - q[2];
      if (ex * ex + ey * ey + ez * ez <= r2)
        by_offset[static_cast<size_t>(((dz + reach) * side + dy + reach) * side + dx + reach)].push_back(j);
    }
  std::vector<uint32_t> out;
  for (const std::vector<uint32_t>& points : by_offset) out.insert(out.end(), points.begin(), points.end());
  return out;
}

}  // namespace

TEST_CASE("exact cuts: the radius search skips only cells wholly beyond the radius") {
  const std::vector<float> pts = cloud();
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  for (float cell : {0.4f, 0.5f}) {
    test::GridFixture g(pts, cell);
    for (float radius : {0.4f, 1.0f}) {
      for (uint32_t i = 0; i < n; i += 97) {
        const float* q = pts.data() + 3u * i;
        CHECK(visited(g.grid, q, radius) == visited_unculled(g.grid, pts.data(), q, radius));
      }
    }
  }
}

TEST_CASE("exact cuts: normals over gathered neighbourhoods are the point-by-point normals, bit for bit") {
  const std::vector<float> pts = cloud();
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  const float radius = 0.4f;
  test::GridFixture g(pts, radius);
  std::vector<float> plain(pts.size(), 0.0f);
  std::vector<uint8_t> plain_has(n, 0);
  const uint32_t plain_count =
      estimate_normals(g.grid, pts.data(), n, radius, plain.data(), plain_has.data());
  CHECK(plain_count > n / 2u);
  // Room for every neighbourhood, and for none of the larger ones (the point-by-point fallback).
  for (uint32_t capacity : {n, 40u}) {
    std::vector<float> x(capacity), y(capacity), z(capacity);
    NeighbourScratch scratch;
    scratch.x = x.data();
    scratch.y = y.data();
    scratch.z = z.data();
    scratch.capacity = capacity;
    std::vector<float> gathered(pts.size(), 0.0f);
    std::vector<uint8_t> gathered_has(n, 0);
    CHECK(estimate_normals(g.grid, pts.data(), n, radius, gathered.data(), gathered_has.data(), scratch) ==
          plain_count);
    CHECK(gathered_has == plain_has);
    CHECK(std::memcmp(gathered.data(), plain.data(), gathered.size() * sizeof(float)) == 0);
  }
}

TEST_CASE("exact cuts: model groups list each model's candidates in list order") {
  // Features 0..9 belong to models 3, 1, 3, 2, 1, 3, 0, 2, 2, 1.
  const uint16_t models[] = {3, 1, 3, 2, 1, 3, 0, 2, 2, 1};
  Candidate list[10];
  for (uint32_t i = 0; i < 10; ++i) list[i] = Candidate{9u - i, i};  // list place i holds feature 9 - i
  ModelGroups g;
  group_by_model(list, 10, models, &g);
  REQUIRE(g.count == 10u);
  for (uint16_t m = 0; m < 5; ++m) {
    std::vector<uint32_t> expected, got;
    for (uint32_t i = 0; i < 10; ++i)
      if (models[list[i].feature] == m) expected.push_back(i);
    for (uint32_t j = first_of_model(g, m); j < g.count && g.model[j] == m; ++j) got.push_back(g.index[j]);
    CHECK(got == expected);
  }
}

TEST_CASE("exact cuts: a bound on the steps decides as the coordinates do") {
  Pcg32 rng(11);
  uint32_t checked = 0;
  for (int i = 0; i < 20000; ++i) {
    // Values on and beside the lattice, near zero and far from it.
    const double scale = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 1000.0 : 1.9e6);
    double v = (2.0 * rng.uniform() - 1.0) * scale;
    if (i % 4 == 0) v = from_steps(static_cast<int32_t>(std::llround(v / kLatticeUnit)));  // on a step
    if (i % 8 == 1) v = std::nextafter(v, INFINITY);
    const int64_t k = first_step_from(v);
    for (int64_t d = -2; d <= 2; ++d) {
      const int64_t j = k + d;
      if (j < INT32_MIN || j > INT32_MAX) continue;
      const bool at_least = from_steps(static_cast<int32_t>(j)) >= v;
      CHECK(at_least == (j >= k));
      ++checked;
    }
    if (std::fabs(v) < kLatticeReach) {
      CHECK(lattice_steps(v) == static_cast<int32_t>(std::llround(v / kLatticeUnit)));
      const double half = (std::floor(v / kLatticeUnit) + 0.5) * kLatticeUnit;  // a tie, or next to one
      CHECK(lattice_steps(half) == static_cast<int32_t>(std::llround(half / kLatticeUnit)));
    }
  }
  CHECK(checked > 90000u);
  CHECK(first_step_from(-INFINITY) == INT32_MIN);
  CHECK(first_step_from(INFINITY) == int64_t{INT32_MAX} + 1);
  for (const double tie : {-2.5, -0.5, 0.5, 2.5, 1234567.5}) {  // halves: away from zero, as llround
    const double v = tie * kLatticeUnit;
    CHECK(lattice_steps(v) == static_cast<int32_t>(std::llround(v / kLatticeUnit)));
  }
}
