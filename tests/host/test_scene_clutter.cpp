// The simulator's non-vehicles of a vehicle's size (scan/scene_clutter.cpp):
// each drawn within its stated dimensions, standing on the ground, and
// varied from draw to draw.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "scan/scene_layout.hpp"

namespace sh = spinhash::host;

namespace {

using Make =
    std::function<sh::PlacedObject(const sh::Terrain&, const Eigen::Vector2d&, double, sh::SeededRandom*)>;

// Length, width and height above the ground (m): the draws' extremes.
struct Dimensions {
  const char* name;
  Make make;
  double length_lo, length_hi, width_lo, width_hi, height_lo, height_hi;
};

constexpr double kTolerance = 1e-6;
constexpr uint32_t kDraws = 40;

}  // namespace

TEST_CASE("vehicle-sized clutter: sheds, containers, bushes and heaps within their dimensions") {
  const Dimensions kinds[] = {
      {"shed", sh::make_shed, 2.4, 6.5, 1.8, 3.6, 2.1, 3.9},
      {"container", sh::make_container, 6.058, 12.192, 2.438, 2.438, 2.591, 2.896},
      {"bush", sh::make_bush, 1.5, 6.0, 1.0, 2.5, 0.8 * 0.85, 2.2},
      {"heap", sh::make_heap, 2.5, 8.0, 2.0, 5.0, 0.8, 2.5},
  };
  const sh::Terrain terrain(sh::level_ground());
  const Eigen::Vector2d at(3.0, -2.0);
  const double ground = terrain.height(at.x(), at.y());
  for (const Dimensions& k : kinds) {
    sh::SeededRandom rng(17);
    double shortest = INFINITY, longest = 0.0;
    for (uint32_t i = 0; i < kDraws; ++i) {
      const sh::PlacedObject p = k.make(terrain, at, 0.3 * i, &rng);
      INFO(k.name, " draw ", i, ": ", p.truth.extent.transpose());
      CHECK(p.mesh.name == k.name);
      CHECK(p.mesh.triangle_count() > 0u);
      const Eigen::Vector3d e = p.truth.extent;
      CHECK(e.x() >= k.length_lo - kTolerance);
      CHECK(e.x() <= k.length_hi + kTolerance);
      CHECK(e.y() >= k.width_lo - kTolerance);
      CHECK(e.y() <= std::min(k.width_hi, e.x()) + kTolerance);  // the length is the longer side
      CHECK(e.z() >= k.height_lo - kTolerance);
      CHECK(e.z() <= k.height_hi + kTolerance);
      CHECK(p.mesh.bounding_box().lo.z() <= ground + kTolerance);  // it stands on the ground, no gap
      CHECK(p.truth.center.head<2>().isApprox(at));
      shortest = std::min(shortest, e.x());
      longest = std::max(longest, e.x());
    }
    CHECK_MESSAGE(longest - shortest > 1.0, k.name);
  }
}

TEST_CASE("vehicle-sized clutter: a footprint turned by the yaw") {
  const sh::Terrain terrain(sh::level_ground());
  sh::SeededRandom a(5), b(5);
  const sh::PlacedObject straight = sh::make_container(terrain, Eigen::Vector2d::Zero(), 0.0, &a);
  const sh::PlacedObject turned = sh::make_container(terrain, Eigen::Vector2d::Zero(), 0.5 * M_PI, &b);
  const auto box_straight = straight.mesh.bounding_box(), box_turned = turned.mesh.bounding_box();
  CHECK(box_straight.hi.x() - box_straight.lo.x() == doctest::Approx(straight.truth.extent.x()));
  CHECK(box_turned.hi.y() - box_turned.lo.y() == doctest::Approx(turned.truth.extent.x()));
  CHECK(turned.truth.heading_deg == doctest::Approx(90.0));
}
