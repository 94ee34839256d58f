// PCA normals (geometry/normals.*) on surfaces with known normals, and their
// orientation: away from a centre, or towards a sensor position.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "geometry/normals.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/grid_fixture.hpp"

using namespace spinhash;

namespace {

constexpr float kNormalRadius = 0.3f;  // m: the neighbourhood of the PCA
const float kCos2Deg = std::cos(2.0f * 3.14159265f / 180.0f);
const float kCos4Deg = std::cos(4.0f * 3.14159265f / 180.0f);

struct Normals {
  std::vector<float> n;
  std::vector<uint8_t> has;
  uint32_t count = 0;
};

Normals estimate(const std::vector<float>& pts) {
  test::GridFixture g(pts, kNormalRadius);
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  Normals out;
  out.n.assign(pts.size(), 0.0f);
  out.has.assign(n, 0);
  out.count = estimate_normals(g.grid, pts.data(), n, kNormalRadius, out.n.data(), out.has.data());
  return out;
}

float dot(const float* a, const float* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

TEST_CASE("normals of a plane are its normal, turned towards the sensor") {
  const std::vector<float> pts = test::plane_grid(2.0f, 0.1f);
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  Normals nm = estimate(pts);
  CHECK(nm.count == n);
  const float up[3] = {0.0f, 0.0f, 1.0f};
  for (uint32_t i = 0; i < n; ++i) CHECK(std::fabs(dot(&nm.n[3 * i], up)) > kCos2Deg);

  const float above[3] = {0.5f, -0.3f, 40.0f}, below[3] = {0.0f, 0.0f, -40.0f};
  orient_normals(pts.data(), n, above, true, nm.n.data(), nm.has.data());
  for (uint32_t i = 0; i < n; ++i) CHECK(nm.n[3 * i + 2] > 0.0f);
  orient_normals(pts.data(), n, below, true, nm.n.data(), nm.has.data());
  for (uint32_t i = 0; i < n; ++i) CHECK(nm.n[3 * i + 2] < 0.0f);
}

TEST_CASE("normals of a sphere are radial and point away from its centre") {
  const float c[3] = {5.0f, -3.0f, 2.0f};
  const std::vector<float> pts = test::fibonacci_sphere(3000, 1.5f, c[0], c[1], c[2]);
  const std::vector<float> truth = test::sphere_normals(pts, c[0], c[1], c[2]);
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  Normals nm = estimate(pts);
  CHECK(nm.count == n);
  orient_normals(pts.data(), n, c, false, nm.n.data(), nm.has.data());
  uint32_t outward = 0;
  for (uint32_t i = 0; i < n; ++i) {
    CHECK(std::fabs(std::sqrt(dot(&nm.n[3 * i], &nm.n[3 * i])) - 1.0f) < 1e-4f);
    outward += dot(&nm.n[3 * i], &truth[3 * i]) > kCos4Deg ? 1u : 0u;
  }
  CHECK(outward == n);
}

TEST_CASE("points with too few neighbours or on a line get no normal") {
  std::vector<float> pts;
  for (int i = 0; i < 40; ++i) pts.insert(pts.end(), {0.02f * static_cast<float>(i), 0.0f, 0.0f});  // a line
  pts.insert(pts.end(), {10.0f, 10.0f, 10.0f, 10.05f, 10.0f, 10.0f, 10.0f, 10.05f, 10.0f});         // 3 alone
  Normals nm = estimate(pts);
  CHECK(nm.count == 0u);
  for (uint8_t h : nm.has) CHECK(h == 0u);
}
