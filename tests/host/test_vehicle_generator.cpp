#include "mesh/vehicle_generator.hpp"
#include "mesh/vehicle_parts.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <utility>

namespace sh = spinhash::host;

namespace {

constexpr uint64_t kSeed = 20240611;

// Every directed edge must be matched by exactly one reverse edge: the
// surface is closed and consistently wound.
bool closed_and_consistent(const sh::Mesh& mesh) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = mesh.triangles[3 * t + k];
      const uint32_t b = mesh.triangles[3 * t + (k + 1) % 3];
      ++edges[{a, b}];
    }
  }
  for (const auto& [edge, count] : edges) {
    if (count != 1) return false;
    const auto reverse = edges.find({edge.second, edge.first});
    if (reverse == edges.end() || reverse->second != 1) return false;
  }
  return true;
}

// Signed volume of each connected part (triangles sharing vertices).
std::vector<double> part_volumes(const sh::Mesh& mesh) {
  std::vector<uint32_t> parent(mesh.vertex_count());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&parent](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 1; k < 3; ++k) parent[find(mesh.triangles[3 * t + k])] = find(mesh.triangles[3 * t]);
  }
  std::map<uint32_t, double> volume;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Eigen::Vector3d a = mesh.vertex(mesh.triangles[3 * t]);
    const Eigen::Vector3d b = mesh.vertex(mesh.triangles[3 * t + 1]);
    const Eigen::Vector3d c = mesh.vertex(mesh.triangles[3 * t + 2]);
    volume[find(mesh.triangles[3 * t])] += a.dot(b.cross(c)) / 6.0;
  }
  std::vector<double> out;
  for (const auto& [root, v] : volume) out.push_back(v);
  return out;
}

}  // namespace

TEST_CASE("vehicle parts are closed, outward-wound solids of the right size") {
  sh::Mesh box;
  sh::add_box(&box, {-1, -2, 0}, {1, 2, 3});
  CHECK(box.triangle_count() == 12);
  CHECK(box.surface_area() == doctest::Approx(2 * (2 * 4 + 2 * 3 + 4 * 3)));
  CHECK(box.signed_volume() == doctest::Approx(24.0));
  CHECK(closed_and_consistent(box));

  sh::Mesh wheel;
  sh::add_cylinder(&wheel, {0, 0, 0.3}, sh::Axis::kY, 0.3, 0.2, 14);
  CHECK(wheel.triangle_count() == 14 * 4 - 4);
  // A 14-gon's area is 14/2 r^2 sin(2 pi/14) of the circle's.
  const double polygon = 7.0 * 0.09 * std::sin(2.0 * M_PI / 14.0);
  CHECK(wheel.signed_volume() == doctest::Approx(polygon * 0.2));
  CHECK(closed_and_consistent(wheel));
  const sh::Box3 bounds = wheel.bounding_box();
  CHECK(bounds.size().y() == doctest::Approx(0.2));
  CHECK(bounds.lo.z() == doctest::Approx(0.0).epsilon(1e-3));
}

TEST_CASE("mesh helpers: append shifts indices, mirroring keeps the winding outward") {
  sh::Mesh a;
  sh::add_box(&a, {0, 0, 0}, {1, 1, 1});
  sh::Mesh b;
  sh::add_box(&b, {2, 0, 0}, {3, 1, 1});
  a.append(b);
  CHECK(a.vertex_count() == 16);
  CHECK(a.triangle_count() == 24);
  CHECK(a.validate().empty());
  CHECK(a.signed_volume() == doctest::Approx(2.0));
  Eigen::Matrix4d mirror = Eigen::Matrix4d::Identity();
  mirror(0, 0) = -1.0;
  a.apply_transform(mirror);
  CHECK(a.signed_volume() == doctest::Approx(2.0));
  CHECK(a.bounding_box().lo.x() == doctest::Approx(-3.0));
  CHECK(closed_and_consistent(a));
}

TEST_CASE("fleets are deterministic and cycle through the families") {
  const std::vector<sh::Mesh> first = sh::generate_fleet(2 * sh::kFamilyCount, kSeed);
  const std::vector<sh::Mesh> again = sh::generate_fleet(2 * sh::kFamilyCount, kSeed);
  REQUIRE(first.size() == 2 * sh::kFamilyCount);
  for (std::size_t i = 0; i < first.size(); ++i) {
    CHECK(first[i].name == again[i].name);
    CHECK(first[i].vertices == again[i].vertices);
    CHECK(first[i].triangles == again[i].triangles);
  }
  const std::vector<sh::Mesh> other = sh::generate_fleet(2 * sh::kFamilyCount, kSeed + 1);
  CHECK(other[0].vertices != first[0].vertices);

  const std::vector<sh::Mesh> four = sh::generate_fleet(4, kSeed);
  CHECK(four[0].name == "sedan-00");
  CHECK(four[1].name == "van-00");
  CHECK(four[2].name == "truck-00");
  CHECK(four[3].name == "tracked-00");
  CHECK(first[7].name == "suv-00");
  CHECK(first[8].name == "sedan-01");

  std::set<std::string> names;
  for (const sh::VehicleSpec& spec : sh::fleet_specs(300, kSeed)) names.insert(spec.name);
  CHECK(names.size() == 300);
  CHECK(sh::generate_fleet(0, kSeed).empty());
  CHECK(sh::fleet_specs(0xFFFFFFFFu, kSeed).size() == sh::kMaxFleetSize);
}

TEST_CASE("a member is the same alone and in a fleet") {
  const sh::Mesh alone = sh::generate_vehicle(sh::Family::kTruck, 3, kSeed);
  const std::vector<sh::Mesh> fleet = sh::generate_fleet(4 * sh::kFamilyCount, kSeed);
  const sh::Mesh& in_fleet = fleet[3 * sh::kFamilyCount + 2];
  CHECK(in_fleet.name == "truck-03");
  CHECK(alone.vertices == in_fleet.vertices);
}

TEST_CASE("every generated vehicle is a valid closed solid standing on z = 0") {
  for (const sh::VehicleSpec& spec : sh::fleet_specs(6 * sh::kFamilyCount, kSeed)) {
    CAPTURE(spec.name);
    const sh::Mesh mesh = sh::build_vehicle(spec);
    CHECK(mesh.name == spec.name);
    CHECK(mesh.validate().empty());
    CHECK(mesh.surface_area() > 10.0);
    CHECK(closed_and_consistent(mesh));
    for (double v : part_volumes(mesh)) CHECK(v > 0.0);
    const sh::Box3 box = mesh.bounding_box();
    CHECK(std::abs(box.lo.z()) < 1e-3);        // wheels or tracks touch the ground
    CHECK(std::abs(box.center().y()) < 1e-4);  // left-right symmetric
    if (!spec.barrel && !spec.spare_wheel) {
      CHECK(std::abs(box.center().x()) < 0.15);
      CHECK(box.size().x() == doctest::Approx(spec.length).epsilon(1e-6));
    }
    // The spec's height is the overall height: roof rack, cargo box, turret.
    CHECK(std::abs(box.size().z() - spec.height) < 1e-6);
    // Mirrors reach out past the body (published widths exclude them).
    CHECK(box.size().y() >= spec.width - 1e-6);
    CHECK(box.size().y() <= spec.width + 0.25);
    CHECK(box.size().z() < 3.8);  // below the scene's layer split (SceneConfig::layer_split_height)
  }
}

TEST_CASE("every member's dimensions are in its body style's real-world ranges") {
  const auto in = [](double v, const sh::DimensionRange& r) { return v >= r.lo - 1e-9 && v <= r.hi + 1e-9; };
  for (const sh::VehicleSpec& spec : sh::fleet_specs(30 * sh::kFamilyCount, kSeed)) {
    const sh::BodyStyleInfo& style = sh::body_style_info(spec.style);
    CAPTURE(spec.name);
    CAPTURE(std::string(style.name));
    CHECK(style.family == spec.family);
    CHECK(in(spec.length, style.length));
    CHECK(in(spec.width, style.width));
    CHECK(in(spec.height, style.height));
    CHECK(spec.belt_height <= spec.height);  // equal: a hull without turret or casemate
    CHECK(spec.ground_clearance < spec.belt_height);
  }
}

TEST_CASE(
    "body styles: each family's slots fill its cycle, and any cycle of members holds each style in its "
    "share") {
  std::map<sh::Family, uint32_t> slots;
  for (uint32_t id = 0; id < sh::kBodyStyleCount; ++id) {
    const sh::BodyStyleInfo& style = sh::body_style_info(static_cast<sh::BodyStyle>(id));
    CHECK(static_cast<uint32_t>(style.style) == id);
    CHECK(style.slots > 0u);
    CHECK(style.length.lo < style.length.hi);
    CHECK(style.width.lo < style.width.hi);
    CHECK(style.height.lo < style.height.hi);
    slots[style.family] += style.slots;
  }
  CHECK(slots.size() == sh::kFamilyCount);
  for (const auto& [family, total] : slots) CHECK(total == sh::kStyleCycle);
  for (uint64_t seed : {kSeed, uint64_t{1}, uint64_t{2}}) {
    for (uint32_t id = 0; id < sh::kBodyStyleCount; ++id) {
      const sh::BodyStyleInfo& style = sh::body_style_info(static_cast<sh::BodyStyle>(id));
      for (uint32_t first : {0u, 7u}) {
        uint32_t held = 0;
        for (uint32_t i = first; i < first + sh::kStyleCycle; ++i)
          held += sh::make_vehicle_spec(style.family, i, seed).style == style.style ? 1u : 0u;
        CAPTURE(std::string(style.name));
        CHECK(held == style.slots);
      }
    }
  }
}

TEST_CASE("the fleet's classes overlap where real ones do") {
  // Published dimensions: the tallest hatchbacks (1.55 m) stand above the
  // lowest crossovers (1.53 m), the tallest SUVs and off-roaders (1.97 m)
  // above the lowest MPVs (1.62 m) and pickups, high-roof vans (2.8 m) above
  // light lorries' cabs, and long vans (7 m) outreach short lorries (5 m).
  const auto range = [](sh::Family family, double sh::DimensionRange::*end,
                        sh::DimensionRange sh::BodyStyleInfo::*dim) {
    double best = (end == &sh::DimensionRange::lo) ? 1e9 : -1e9;
    for (uint32_t id = 0; id < sh::kBodyStyleCount; ++id) {
      const sh::BodyStyleInfo& s = sh::body_style_info(static_cast<sh::BodyStyle>(id));
      if (s.family != family) continue;
      const double v = (s.*dim).*end;
      best = (end == &sh::DimensionRange::lo) ? std::min(best, v) : std::max(best, v);
    }
    return best;
  };
  const auto lo = &sh::DimensionRange::lo;
  const auto hi = &sh::DimensionRange::hi;
  const auto height = &sh::BodyStyleInfo::height;
  const auto length = &sh::BodyStyleInfo::length;
  CHECK(range(sh::Family::kSedan, hi, height) > range(sh::Family::kSuv, lo, height));
  CHECK(range(sh::Family::kSuv, hi, height) > range(sh::Family::kVan, lo, height));
  CHECK(range(sh::Family::kSuv, hi, height) > range(sh::Family::kPickup, lo, height));
  CHECK(range(sh::Family::kVan, hi, height) > range(sh::Family::kTruck, lo, height));
  CHECK(range(sh::Family::kVan, hi, length) > range(sh::Family::kTruck, lo, length));
  CHECK(range(sh::Family::kTruck, hi, length) > range(sh::Family::kBus, lo, length));
  CHECK(range(sh::Family::kApc, hi, height) > range(sh::Family::kTracked, lo, height));
}

TEST_CASE("members of a family differ") {
  // Look-alikes: same layout, but any two of ten members of a style differ
  // by at least 5 cm in some overall dimension (members of two styles
  // differ in layout).
  for (uint32_t family = 0; family < sh::kFamilyCount; ++family) {
    std::vector<sh::VehicleSpec> specs;
    for (uint32_t i = 0; i < 10; ++i)
      specs.push_back(sh::make_vehicle_spec(static_cast<sh::Family>(family), i, kSeed));
    for (std::size_t i = 0; i < specs.size(); ++i) {
      for (std::size_t j = i + 1; j < specs.size(); ++j) {
        if (specs[i].style != specs[j].style) continue;
        CAPTURE(specs[i].name);
        CAPTURE(specs[j].name);
        const double apart =
            std::max({std::abs(specs[i].length - specs[j].length), std::abs(specs[i].width - specs[j].width),
                      std::abs(specs[i].height - specs[j].height)});
        CHECK(apart > 0.05);
      }
    }
  }
}

TEST_CASE("family names round trip") {
  for (uint32_t id = 0; id < sh::kFamilyCount; ++id) {
    sh::Family parsed;
    REQUIRE(sh::parse_family(sh::family_name(static_cast<sh::Family>(id)), &parsed));
    CHECK(static_cast<uint32_t>(parsed) == id);
  }
  sh::Family unused;
  CHECK_FALSE(sh::parse_family("hovercraft", &unused));
}

TEST_CASE("ground patch: flat or bumpy square facing up") {
  const sh::Mesh flat = sh::make_ground_patch(10.0, 0.0);
  CHECK(flat.validate().empty());
  CHECK(flat.surface_area() == doctest::Approx(400.0));
  const sh::Box3 box = flat.bounding_box();
  CHECK(box.lo.z() == 0.0);
  CHECK(box.hi.z() == 0.0);
  CHECK(box.lo.x() == doctest::Approx(-10.0));
  for (std::size_t t = 0; t < flat.triangle_count(); ++t) {
    const Eigen::Vector3d a = flat.vertex(flat.triangles[3 * t]);
    const Eigen::Vector3d n =
        (flat.vertex(flat.triangles[3 * t + 1]) - a).cross(flat.vertex(flat.triangles[3 * t + 2]) - a);
    REQUIRE(n.z() > 0.0);
  }
  const sh::Mesh bumpy = sh::make_ground_patch(5.0, -0.5, 0.03, 7);
  const sh::Box3 b = bumpy.bounding_box();
  CHECK(b.lo.z() >= -0.53);
  CHECK(b.hi.z() <= -0.47);
  CHECK(b.hi.z() - b.lo.z() > 0.03);
  CHECK(bumpy.vertices == sh::make_ground_patch(5.0, -0.5, 0.03, 7).vertices);
  CHECK(sh::make_ground_patch(-1.0, 0.0).triangle_count() == 0);
  CHECK(sh::make_ground_patch(NAN, 0.0).triangle_count() == 0);
  CHECK(sh::make_ground_patch(1e9, 0.0).vertex_count() <= 401u * 401u);
}
