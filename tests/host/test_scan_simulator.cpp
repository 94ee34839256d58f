#include "geometry_test_support.hpp"
#include "mesh/vehicle_generator.hpp"
#include "mesh/vehicle_parts.hpp"
#include "scan/ray_caster.hpp"
#include "scan/scan_simulator.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>

namespace sh = spinhash::host;

namespace {

const Eigen::Vector3d kBoxLo(-1.0, -1.0, 0.0);
const Eigen::Vector3d kBoxHi(1.0, 1.0, 2.0);

sh::Mesh test_box() {
  sh::Mesh box;
  box.name = "box";
  sh::add_box(&box, kBoxLo, kBoxHi);
  return box;
}

Eigen::Vector3d point(const sh::ScanResult& scan, std::size_t i) {
  return {scan.xyz[3 * i], scan.xyz[3 * i + 1], scan.xyz[3 * i + 2]};
}

// Entry distance of the ray o + t d into the box (slab method), or NaN.
double ray_box_entry(const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  double t0 = 0.0;
  double t1 = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double a = (kBoxLo[k] - o[k]) / d[k];
    const double b = (kBoxHi[k] - o[k]) / d[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  return t0 <= t1 ? t0 : NAN;
}

// Index of the view that produced point i (points come in view order).
std::size_t view_of(const sh::ScanResult& scan, std::size_t i) {
  std::size_t view = 0;
  for (std::size_t end = scan.view_points[0]; i >= end; end += scan.view_points[++view]) {
  }
  return view;
}

sh::ScanOptions box_options() {
  sh::ScanOptions o;
  o.views = 3;
  o.azimuth_start_deg = 10.0;
  o.seed = 3;
  return o;
}

}  // namespace

TEST_CASE("ray caster: hits, misses, geometry ids") {
  sh::RayCaster caster;
  std::string error;
  sh::Mesh empty;
  REQUIRE(caster.add_mesh(empty, Eigen::Vector3d::Zero(), &error));        // id 0, nothing to hit
  REQUIRE(caster.add_mesh(test_box(), Eigen::Vector3d(0, 0, 1), &error));  // id 1, centred
  REQUIRE(caster.commit(&error));
  std::vector<sh::Ray> rays = {{{5, 0, 0}, {-1, 0, 0}}, {{5, 0, 0}, {1, 0, 0}}, {{0, 0, 9}, {0, 0, -2}}};
  std::vector<sh::RayHit> hits;
  REQUIRE(caster.cast(rays, &hits, &error));
  CHECK(hits[0].geometry == 1);
  CHECK(hits[0].distance == doctest::Approx(4.0));
  CHECK_FALSE(hits[1].hit());
  CHECK(hits[2].distance == doctest::Approx(4.0));  // direction length 2: distance in its units

  sh::RayCaster uncommitted;
  CHECK_FALSE(uncommitted.cast(rays, &hits, &error));
  sh::Mesh bad = test_box();
  bad.triangles[0] = 99;
  CHECK_FALSE(uncommitted.add_mesh(bad, Eigen::Vector3d::Zero(), &error));
  CHECK(error.find("index") != std::string::npos);
}

TEST_CASE("noise-free box scan: points on the visible surface at the expected density") {
  const sh::ScanOptions options = box_options();
  const sh::ScanResult scan = sh::simulate_scan(test_box(), options);
  REQUIRE_MESSAGE(scan.ok(), scan.error);
  REQUIRE(scan.view_points.size() == 3);
  REQUIRE(scan.viewpoints.size() == 3);
  std::size_t top = 0;
  std::size_t on_bottom = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const Eigen::Vector3d p = point(scan, i);
    worst = std::max(worst, sh::test::distance_to_box_surface(p, kBoxLo, kBoxHi));
    if (p.z() > kBoxHi.z() - 1e-4) ++top;
    if (p.z() < 1e-4 && std::abs(p.x()) < 0.99 && std::abs(p.y()) < 0.99) ++on_bottom;
    REQUIRE(scan.on_object[i] == 1);
  }
  CHECK(worst < 1e-4);
  CHECK(on_bottom == 0);
  // The top (4 m^2) is seen by all 3 views at 45 degrees: 3 * 4 cos45 / s^2.
  const double expected_top = 3.0 * 4.0 * std::cos(M_PI / 4) / (0.05 * 0.05);
  MESSAGE("box top: " << top << " points, expected about " << expected_top);
  CHECK(top == doctest::Approx(expected_top).epsilon(0.15));
  // Sensors on the hemisphere at 45 degrees elevation, aimed at the centre.
  const Eigen::Vector3d center(0, 0, 1);
  const double radius = (scan.viewpoints[0] - center).norm();
  for (const Eigen::Vector3d& v : scan.viewpoints) {
    CHECK((v - center).norm() == doctest::Approx(radius));
    CHECK((v - center).z() / radius == doctest::Approx(std::sin(M_PI / 4)));
  }
  const double step = std::atan2(scan.viewpoints[1].y(), scan.viewpoints[1].x()) -
                      std::atan2(scan.viewpoints[0].y(), scan.viewpoints[0].x());
  CHECK(step * 180.0 / M_PI == doctest::Approx(45.0));
  CHECK(scan.true_pose.isApprox(Eigen::Matrix4d::Identity()));
}

TEST_CASE("noise is Gaussian along the rays with the requested sigma") {
  for (double sigma : {0.05, 0.10}) {
    sh::ScanOptions options = box_options();
    options.noise_sigma = sigma;
    const sh::ScanResult scan = sh::simulate_scan(test_box(), options);
    REQUIRE_MESSAGE(scan.ok(), scan.error);
    double sum = 0.0;
    double sum_sq = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < scan.size(); ++i) {
      const Eigen::Vector3d p = point(scan, i);
      const Eigen::Vector3d o = scan.viewpoints[view_of(scan, i)];
      const double range = (p - o).norm();
      const double truth = ray_box_entry(o, (p - o) / range);
      if (std::isnan(truth)) continue;  // grazing ray whose noisy point left the box's shadow
      sum += range - truth;
      sum_sq += (range - truth) * (range - truth);
      ++n;
    }
    REQUIRE(n > scan.size() * 9 / 10);
    const double mean = sum / n;
    const double std_dev = std::sqrt(sum_sq / n - mean * mean);
    MESSAGE("noise sigma " << sigma << ": residual along rays mean " << mean << " std " << std_dev << " over "
                           << n << " points");
    CHECK(std::abs(mean) < 0.1 * sigma);
    CHECK(std_dev == doctest::Approx(sigma).epsilon(0.2));
  }
}

TEST_CASE("random pose: true_pose maps the model onto the scan; offset survives in double") {
  const sh::Mesh sedan = sh::generate_vehicle(sh::Family::kSedan, 1, 5);
  sh::ScanOptions options = sh::query_scan_options(0.0, 42);
  options.random_pose = true;
  options.random_tilt = true;
  options.offset[0] = 500000.0;
  options.offset[1] = 4000000.0;
  options.offset[2] = 100.0;
  const sh::ScanResult scan = sh::simulate_scan(sedan, options);
  REQUIRE_MESSAGE(scan.ok(), scan.error);
  const Eigen::Matrix4d pose = scan.true_pose;
  CHECK(pose.topLeftCorner<3, 3>().determinant() == doctest::Approx(1.0));
  CHECK(std::abs(pose(0, 3) - 500000.0) <= sh::kPoseTranslationRange);
  CHECK(std::abs(pose(1, 3) - 4000000.0) <= sh::kPoseTranslationRange);
  const Eigen::Matrix4d inverse = pose.inverse();
  double worst = 0.0;
  for (std::size_t i = 0; i < scan.size(); i += 23) {
    const Eigen::Vector3d model_point = (inverse * point(scan, i).homogeneous()).head<3>();
    worst = std::max(worst, sh::test::distance_to_mesh(model_point, sedan));
  }
  CHECK(worst < 1e-3);  // float ray casting near the object: sub-millimetre

  // The same scan without the offset differs by exactly the offset (a float
  // pipeline would be off by decimetres at 4,000,000 m).
  sh::ScanOptions local = options;
  local.offset[0] = local.offset[1] = local.offset[2] = 0.0;
  const sh::ScanResult near = sh::simulate_scan(sedan, local);
  REQUIRE(near.size() == scan.size());
  double drift = 0.0;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const Eigen::Vector3d shifted = point(scan, i) - Eigen::Vector3d(500000.0, 4000000.0, 100.0);
    drift = std::max(drift, (shifted - point(near, i)).norm());
  }
  CHECK(drift < 1e-6);
}

TEST_CASE("scans are deterministic for a seed and change with it") {
  const sh::Mesh van = sh::generate_vehicle(sh::Family::kVan, 0, 5);
  const sh::ScanResult a = sh::simulate_scan(van, sh::query_scan_options(0.1, 7));
  const sh::ScanResult b = sh::simulate_scan(van, sh::query_scan_options(0.1, 7));
  const sh::ScanResult c = sh::simulate_scan(van, sh::query_scan_options(0.1, 8));
  REQUIRE(a.ok());
  CHECK(a.xyz == b.xyz);
  CHECK(a.viewpoints == b.viewpoints);
  CHECK(a.xyz != c.xyz);
  CHECK_FALSE(a.viewpoints[0].isApprox(c.viewpoints[0]));
}

TEST_CASE("occlusion hides the requested fraction of the object") {
  const sh::Mesh truck = sh::generate_vehicle(sh::Family::kTruck, 0, 5);
  sh::ScanOptions options = sh::query_scan_options(0.05, 11);
  const sh::ScanResult full = sh::simulate_scan(truck, options);
  options.occlusion = 0.3;
  const sh::ScanResult hidden = sh::simulate_scan(truck, options);
  REQUIRE(hidden.ok());
  CHECK(double(hidden.size()) == doctest::Approx(0.7 * full.size()).epsilon(0.01));
  CHECK(hidden.xyz == sh::simulate_scan(truck, options).xyz);
  // The survivors are a subset of the unoccluded scan.
  std::size_t j = 0;
  for (std::size_t i = 0; i < hidden.size(); ++i) {
    while (j < full.size() && point(full, j) != point(hidden, i)) ++j;
  }
  CHECK(j < full.size());
}

TEST_CASE("ground is scanned with the object, level and labelled") {
  const sh::Mesh sedan = sh::generate_vehicle(sh::Family::kSedan, 0, 5);
  const sh::Mesh ground = sh::make_ground_patch(6.0, 0.0);
  sh::ScanOptions options = sh::query_scan_options(0.0, 3);
  options.ground = &ground;
  options.random_pose = true;
  const sh::ScanResult scan = sh::simulate_scan(sedan, options);
  REQUIRE_MESSAGE(scan.ok(), scan.error);
  std::size_t ground_points = 0;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (scan.on_object[i]) continue;
    ++ground_points;
    REQUIRE(scan.xyz[3 * i + 2] == doctest::Approx(scan.true_pose(2, 3)));
  }
  CHECK(ground_points > 1000);
  CHECK(scan.size() - ground_points > 5000);
}

TEST_CASE("bad scan options and models fail cleanly") {
  const sh::Mesh box = test_box();
  const auto fails = [&box](const sh::ScanOptions& o) {
    const sh::ScanResult r = sh::simulate_scan(box, o);
    return !r.ok() && r.xyz.empty();
  };
  sh::ScanOptions o = box_options();
  o.views = 0;
  CHECK(fails(o));
  o = box_options();
  o.point_spacing = 0.0;
  CHECK(fails(o));
  o.point_spacing = 1e-5;  // far beyond kMaxRaysPerView
  CHECK(fails(o));
  o = box_options();
  o.noise_sigma = NAN;
  CHECK(fails(o));
  o = box_options();
  o.elevation_deg = 120.0;
  CHECK(fails(o));
  o = box_options();
  o.occlusion = 1.0;
  CHECK(fails(o));
  o = box_options();
  o.offset[1] = INFINITY;
  CHECK(fails(o));
  CHECK_FALSE(sh::simulate_scan(sh::Mesh{}, box_options()).ok());
  sh::Mesh nan_box = box;
  nan_box.vertices[4] = NAN;
  CHECK_FALSE(sh::simulate_scan(nan_box, box_options()).ok());
  o = box_options();
  o.elevation_deg = 90.0;  // straight down: still a valid frame
  CHECK(sh::simulate_scan(box, o).ok());
}

TEST_CASE("paper presets and measured scan sizes") {
  const sh::ScanOptions model = sh::model_scan_options();
  CHECK(model.views == 8);
  CHECK(model.elevation_deg == 45.0);
  CHECK(model.azimuth_step_deg == 45.0);
  CHECK(model.noise_sigma == 0.0);
  const sh::ScanOptions query = sh::query_scan_options(0.1, 9);
  CHECK(query.views == 3);
  CHECK(query.noise_sigma == 0.1);
  CHECK(std::isnan(query.azimuth_start_deg));

  const sh::Mesh sedan = sh::generate_vehicle(sh::Family::kSedan, 0, 1);
  const auto start = std::chrono::steady_clock::now();
  const sh::ScanResult scan = sh::simulate_scan(sedan, query);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(scan.ok());
  MESSAGE("sedan " << sedan.bounding_box().size().x() << " m, 0.05 m spacing: points per view "
                   << scan.view_points[0] << " " << scan.view_points[1] << " " << scan.view_points[2]
                   << ", query scan " << ms << " ms");
  for (uint32_t n : scan.view_points) {
    CHECK(n > 2000);
    CHECK(n < 6000);
  }
}
