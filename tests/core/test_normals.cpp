// PCA normals (geometry/normals.*) on surfaces with known normals, and their
// orientation: up within 45 degrees of level, else away from the vertical
// through a centre; or towards a sensor position.
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

TEST_CASE("normals of a sphere are radial: up on the caps, away from the centre on the band between") {
  const float c[3] = {5.0f, -3.0f, 2.0f};
  const std::vector<float> pts = test::fibonacci_sphere(3000, 1.5f, c[0], c[1], c[2]);
  const std::vector<float> truth = test::sphere_normals(pts, c[0], c[1], c[2]);
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  Normals nm = estimate(pts);
  CHECK(nm.count == n);
  orient_normals(pts.data(), n, c, false, nm.n.data(), nm.has.data());
  // Within a few degrees of 45 degrees from level either side may win.
  const float kBandLow = 0.66f, kBandHigh = 0.75f;
  uint32_t as_expected = 0, tested = 0, lower_cap = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const float* t = &truth[3 * i];
    CHECK(std::fabs(std::sqrt(dot(&nm.n[3 * i], &nm.n[3 * i])) - 1.0f) < 1e-4f);
    if (std::fabs(t[2]) > kBandLow && std::fabs(t[2]) < kBandHigh) continue;
    ++tested;
    const bool lower = t[2] <= -kBandHigh;  // seen from above it would face up: the outward normal turned
    lower_cap += lower ? 1u : 0u;
    const float d = dot(&nm.n[3 * i], t);
    as_expected += (lower ? -d : d) > kCos4Deg ? 1u : 0u;
  }
  CHECK(lower_cap > n / 10u);
  CHECK(tested > n * 9u / 10u);
  CHECK(as_expected == tested);
}

TEST_CASE("a hood below the centroid of an airborne scan faces up, the sides face out") {
  // A roof 1.4 m up over most of the scan, a hood 0.6 m lower in front and
  // one side wall: the centroid lies above the hood.
  std::vector<float> pts;
  const std::vector<float> patch = test::plane_grid(0.6f, 0.05f);
  auto add = [&](float x0, float y0, float z0, bool vertical) {
    for (size_t i = 0; i < patch.size(); i += 3)
      if (vertical)
        pts.insert(pts.end(), {x0 + patch[i], y0, z0 + patch[i + 1]});
      else
        pts.insert(pts.end(), {x0 + patch[i], y0 + patch[i + 1], z0});
  };
  for (float x : {-1.2f, 0.0f, 1.2f}) add(x, 0.0f, 1.4f, false);  // roof
  add(2.6f, 0.0f, 0.8f, false);                                   // hood
  add(0.0f, 0.9f, 0.6f, true);                                    // side wall at y = 0.9
  const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
  Normals nm = estimate(pts);
  float c[3] = {0.0f, 0.0f, 0.0f};
  for (uint32_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) c[a] += pts[3 * i + a] / static_cast<float>(n);
  REQUIRE(c[2] > 0.9f);  // above the hood
  orient_normals(pts.data(), n, c, false, nm.n.data(), nm.has.data());
  uint32_t hood = 0, hood_up = 0, side = 0, side_out = 0;
  for (uint32_t i = 0; i < n; ++i) {
    if (!nm.has[i]) continue;
    const float* p = &pts[3 * i];
    const float* v = &nm.n[3 * i];
    if (p[0] > 2.05f && p[2] < 0.85f) hood += 1u, hood_up += v[2] > kCos4Deg ? 1u : 0u;
    // Away from the roof's edge, whose neighbourhood mixes both planes.
    if (std::fabs(p[1] - 0.9f) < 1e-4f && p[2] < 1.0f) side += 1u, side_out += v[1] > kCos4Deg ? 1u : 0u;
  }
  CHECK(hood > 100u);
  CHECK(hood_up == hood);
  CHECK(side > 100u);
  CHECK(side_out == side);
}

TEST_CASE("points with too few neighbours or on a line get no normal") {
  std::vector<float> pts;
  for (int i = 0; i < 40; ++i) pts.insert(pts.end(), {0.02f * static_cast<float>(i), 0.0f, 0.0f});  // a line
  pts.insert(pts.end(), {10.0f, 10.0f, 10.0f, 10.05f, 10.0f, 10.0f, 10.0f, 10.05f, 10.0f});         // 3 alone
  Normals nm = estimate(pts);
  CHECK(nm.count == 0u);
  for (uint8_t h : nm.has) CHECK(h == 0u);
}
