// Ingestion and resampling (geometry/resample.*): re-centring in double with
// deterministic thinning, one point per cell, basis points, even thinning.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "geometry/resample.hpp"
#include "support/grid_fixture.hpp"

using namespace spinhash;

namespace {

// 10 x 10 points at odd multiples of 5 cm (0.05 .. 0.95), z = 0.05: with
// 0.2 m cells no point lies on a cell boundary, and every cell holds 2 x 2.
std::vector<float> offset_grid() {
  std::vector<float> pts;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) pts.insert(pts.end(), {0.05f + 0.1f * i, 0.05f + 0.1f * j, 0.05f});
  return pts;
}
constexpr float kCell = 0.2f;

}  // namespace

TEST_CASE("recentre subtracts the double mean, keeps georeferenced precision and drops non-finite points") {
  const double e = 431000.0, n = 4020000.0, z = 85.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> xyz{e + 1.0, n + 2.0, z + 3.0, nan,     n, z,
                                e - 1.0, n - 2.0, z - 3.0, e + 3.0, n, z};
  CloudView cloud;
  cloud.xyz_d = xyz.data();
  cloud.count = 4;
  double origin[3];
  float out[12];
  REQUIRE(recentre(cloud, 4, origin, out) == 3u);
  CHECK(origin[0] == doctest::Approx(e + 1.0));  // (e+1 + e-1 + e+3) / 3
  CHECK(origin[1] == doctest::Approx(n));
  CHECK(origin[2] == doctest::Approx(z));
  const float expected[9] = {0.0f, 2.0f, 3.0f, -2.0f, -2.0f, -3.0f, 2.0f, 0.0f, 0.0f};
  for (int k = 0; k < 9; ++k) CHECK(out[k] == doctest::Approx(expected[k]).epsilon(1e-6));

  // Thinning to 2 of 4 takes points 0 and 2 (i * n / keep).
  REQUIRE(recentre(cloud, 2, origin, out) == 2u);
  CHECK(origin[0] == doctest::Approx(e));
  CHECK(out[0] == doctest::Approx(1.0f));
  CHECK(out[3] == doctest::Approx(-1.0f));
}

TEST_CASE("recentre's thinning takes the points i * n / keep for every n and keep") {
  for (uint32_t n = 1; n <= 40; ++n) {
    std::vector<float> xyz;
    for (uint32_t i = 0; i < n; ++i) xyz.insert(xyz.end(), {static_cast<float>(i), 0.0f, 0.0f});
    CloudView cloud;
    cloud.xyz_f = xyz.data();
    cloud.count = n;
    for (uint32_t keep = 1; keep <= n; ++keep) {
      CAPTURE(n);
      CAPTURE(keep);
      double origin[3];
      std::vector<float> out(3u * keep);
      REQUIRE(recentre(cloud, keep, origin, out.data()) == keep);
      for (uint32_t i = 0; i < keep; ++i) {
        const double picked = static_cast<double>(out[3u * i]) + origin[0];
        CHECK(picked == doctest::Approx(static_cast<double>(static_cast<uint64_t>(i) * n / keep)));
      }
    }
  }
}

TEST_CASE("equalise_density leaves one point per occupied cell, at the cell's centroid") {
  const std::vector<float> pts = offset_grid();
  test::GridFixture g(pts, kCell);
  std::vector<float> out(pts.size());
  REQUIRE(equalise_density(g.grid, pts.data(), out.data()) == 25u);
  for (uint32_t c = 0; c < 25; ++c) {
    // Centroids sit at 0.1 + 0.2 k on x and y.
    const float fx = (out[3 * c] - 0.1f) / 0.2f, fy = (out[3 * c + 1] - 0.1f) / 0.2f;
    CHECK(std::fabs(fx - std::round(fx)) < 1e-4f);
    CHECK(std::fabs(fy - std::round(fy)) < 1e-4f);
    CHECK(out[3 * c + 2] == doctest::Approx(0.05f));
  }
}

TEST_CASE("select_basis_points takes the oriented point nearest each cell's centroid of oriented points") {
  const std::vector<float> pts = offset_grid();
  test::GridFixture g(pts, kCell);
  std::vector<uint8_t> has(100, 1);
  // Cell (0,0) holds points 0, 1, 10, 11: only 11 oriented there -> it is chosen.
  has[0] = has[1] = has[10] = 0;
  // Cell (4,4) holds 88, 89, 98, 99: none oriented -> no basis point.
  has[88] = has[89] = has[98] = has[99] = 0;
  std::vector<uint32_t> chosen(100);
  const uint32_t count = select_basis_points(g.grid, pts.data(), has.data(), chosen.data());
  CHECK(count == 24u);
  bool has11 = false;
  for (uint32_t k = 0; k < count; ++k) {
    CHECK(has[chosen[k]] == 1u);
    has11 = has11 || chosen[k] == 11u;
    CHECK(chosen[k] != 0u);
  }
  CHECK(has11);
}

TEST_CASE("thin_evenly keeps keep of n indices spread evenly, in place") {
  uint32_t idx[10] = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
  REQUIRE(thin_evenly(idx, 10, 4) == 4u);  // j * 10 / 4 = 0, 2, 5, 7
  CHECK(idx[0] == 10u);
  CHECK(idx[1] == 12u);
  CHECK(idx[2] == 15u);
  CHECK(idx[3] == 17u);
  uint32_t few[3] = {7, 8, 9};
  CHECK(thin_evenly(few, 3, 5) == 3u);  // nothing to thin
  CHECK(few[2] == 9u);
}
