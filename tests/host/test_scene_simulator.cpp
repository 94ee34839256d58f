// The tile simulator (scan/scene_simulator.hpp) and `spinhash scan-scene`:
// terrain follows the slope, vehicles rest on it, the parked pair's gap,
// the tree over a vehicle, nothing intersects, determinism, bounds, errors.
#include "cli_runner.hpp"
#include "cloud/las_reader.hpp"
#include "mesh/mesh_writer.hpp"
#include "mesh/vehicle_generator.hpp"
#include "scan/scan_simulator.hpp"
#include "scan/scene_layout.hpp"
#include "scan/scene_simulator.hpp"
#include "scan/scene_terrain.hpp"

#include <doctest/doctest.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace sh = spinhash::host;
using spinhash::host::test::contains;
using spinhash::host::test::run_spinhash;
using spinhash::host::test::shell_quoted;
using spinhash::host::test::TempDir;

namespace {

constexpr double kPi = 3.141592653589793;

const std::vector<sh::Mesh>& fleet() {
  static const std::vector<sh::Mesh> f = sh::generate_fleet(sh::kFamilyCount, 1);  // one of each family
  return f;
}

const sh::Mesh& mesh_named(const std::string& name) {
  for (const sh::Mesh& m : fleet())
    if (m.name == name) return m;
  FAIL("no mesh " << name);
  return fleet()[0];
}

// Terrain and vehicles only.
sh::SceneOptions bare_options(double slope) {
  sh::SceneOptions o;
  o.slope_deg = slope;
  o.trees = o.buildings = o.walls = o.crates = 0;
  o.noise_sigma = 0.0;
  return o;
}

Eigen::Vector3d offset_of(const sh::SceneOptions& o) { return {o.offset[0], o.offset[1], o.offset[2]}; }

// Least-squares plane z = a x + b y + c through the points of class 2, in
// coordinates relative to `origin`; returns (a, b, c).
Eigen::Vector3d fit_ground(const sh::SceneScan& s, const Eigen::Vector3d& origin) {
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.classification[i] != 2) continue;
    const Eigen::Vector3d row(s.xyz[3 * i] - origin.x(), s.xyz[3 * i + 1] - origin.y(), 1.0);
    ata += row * row.transpose();
    atb += row * (s.xyz[3 * i + 2] - origin.z());
  }
  return ata.ldlt().solve(atb);
}

double tilt_deg(const Eigen::Vector3d& up) { return std::acos(up.normalized().z()) * 180.0 / kPi; }

std::vector<Eigen::Vector3d> posed_vertices(const sh::Mesh& m, const Eigen::Matrix4d& pose) {
  std::vector<Eigen::Vector3d> v;
  for (std::size_t i = 0; i < m.vertex_count(); ++i)
    v.push_back(pose.topLeftCorner<3, 3>() * m.vertex(i) + pose.topRightCorner<3, 1>());
  return v;
}

// Oriented footprint rectangles of the truth overlap (separating axes).
bool truth_overlap(const sh::SceneTruth& a, const sh::SceneTruth& b) {
  const double ha = a.heading_deg * kPi / 180.0, hb = b.heading_deg * kPi / 180.0;
  const Eigen::Vector2d axes[4] = {{std::cos(ha), std::sin(ha)},
                                   {-std::sin(ha), std::cos(ha)},
                                   {std::cos(hb), std::sin(hb)},
                                   {-std::sin(hb), std::cos(hb)}};
  const Eigen::Vector2d d = (b.center - a.center).head<2>();
  for (const Eigen::Vector2d& u : axes) {
    const double ra =
        0.5 * (a.extent.x() * std::abs(axes[0].dot(u)) + a.extent.y() * std::abs(axes[1].dot(u)));
    const double rb =
        0.5 * (b.extent.x() * std::abs(axes[2].dot(u)) + b.extent.y() * std::abs(axes[3].dot(u)));
    if (std::abs(d.dot(u)) > ra + rb) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("scan-scene: terrain hits lie on a plane of the asked slope, georeferenced") {
  for (double slope : {0.0, 6.0, 12.0}) {
    sh::SceneOptions o = bare_options(slope);
    o.vehicles = 0;
    o.bump_height = o.curb_height = 0.0;
    o.noise_sigma = 0.02;
    const sh::SceneScan s = sh::simulate_scene({}, {}, o);
    REQUIRE(s.ok());
    REQUIRE(s.size() > 100000);  // 40 x 40 m at 0.1 m: ~160 000
    CHECK(s.size() < 200000);
    const Eigen::Vector3d abc = fit_ground(s, offset_of(o));
    CHECK(std::abs(tilt_deg({-abc.x(), -abc.y(), 1.0}) - slope) < 0.05);
    double residual2 = 0.0;
    double max_dx = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      CHECK_MESSAGE(s.classification[i] == 2, "only terrain in a bare tile");
      const double x = s.xyz[3 * i] - o.offset[0], y = s.xyz[3 * i + 1] - o.offset[1];
      const double r = s.xyz[3 * i + 2] - o.offset[2] - (abc.x() * x + abc.y() * y + abc.z());
      residual2 += r * r;
      max_dx = std::max({max_dx, std::abs(x), std::abs(y)});
    }
    CHECK(std::sqrt(residual2 / s.size()) < 0.03);  // the range noise, projected
    CHECK(max_dx <= 20.1);  // inside the 40 m tile round the offset (noise moves points a little)
    CHECK(max_dx > 19.5);
  }
}

TEST_CASE("scan-scene: the merged views give about 1 / spacing^2 points per m^2 of ground") {
  for (double spacing : {0.1, 0.15}) {
    sh::SceneOptions o = bare_options(0.0);
    o.vehicles = 0;
    o.point_spacing = spacing;
    const sh::SceneScan s = sh::simulate_scene({}, {}, o);
    REQUIRE(s.ok());
    const double expected = o.size * o.size / (spacing * spacing);
    CHECK(double(s.size()) == doctest::Approx(expected).epsilon(0.1));
  }
}

TEST_CASE("scan-scene: vehicles rest on the ground, their up axis tilted with the slope") {
  sh::SceneOptions o = bare_options(12.0);
  o.bump_height = o.curb_height = 0.0;  // a plane: the tilt must equal the slope
  o.vehicles = 4;
  const sh::SceneScan s = sh::simulate_scene(fleet(), {}, o);
  REQUIRE(s.ok());
  const Eigen::Vector3d abc = fit_ground(s, offset_of(o));  // measured from the terrain hits
  const Eigen::Vector3d ground_up = Eigen::Vector3d(-abc.x(), -abc.y(), 1.0).normalized();
  uint32_t vehicles = 0;
  for (const sh::SceneTruth& t : s.objects) {
    REQUIRE(t.kind == sh::SceneObjectKind::kVehicle);
    ++vehicles;
    const Eigen::Vector3d up = t.pose.topLeftCorner<3, 3>().col(2);
    CHECK(tilt_deg(up) == doctest::Approx(12.0).epsilon(0.02));
    CHECK(std::acos(std::min(1.0, up.dot(ground_up))) * 180.0 / kPi < 0.3);
    // Its lowest vertex touches the measured ground; none is below it.
    double lowest = INFINITY;
    for (const Eigen::Vector3d& p : posed_vertices(mesh_named(t.model), t.pose)) {
      const Eigen::Vector3d q = p - offset_of(o);
      lowest = std::min(lowest, q.z() - (abc.x() * q.x() + abc.y() * q.y() + abc.z()));
    }
    CHECK(std::abs(lowest) < 0.02);
    CHECK(t.points > 300);  // seen
  }
  CHECK(vehicles == 4);
}

TEST_CASE(
    "scan-scene: on bumpy terrain a vehicle's lowest vertex touches the surface, never across the curb") {
  sh::SceneOptions o = bare_options(8.0);
  o.bump_height = 0.4;
  o.vehicles = 8;  // crowded: some would land across the curb
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    o.seed = seed;
    const sh::SceneScan s = sh::simulate_scene(fleet(), {}, o);
    REQUIRE(s.ok());
    sh::TerrainSpec spec;
    spec.size = o.size, spec.slope_deg = o.slope_deg, spec.bump_height = o.bump_height;
    spec.curb_height = o.curb_height, spec.seed = seed;
    const sh::Terrain terrain(spec);
    for (const sh::SceneTruth& t : s.objects) {
      double lowest = INFINITY;
      for (const Eigen::Vector3d& p : posed_vertices(mesh_named(t.model), t.pose)) {
        const Eigen::Vector3d q = p - offset_of(o);
        lowest = std::min(lowest, q.z() - terrain.height(q.x(), q.y()));
      }
      CHECK(std::abs(lowest) < 0.01);
      // Never across the curb: every footprint corner on one side of it.
      const double h = t.heading_deg * kPi / 180.0;
      const Eigen::Vector2d c = (t.center - offset_of(o)).head<2>(), ax(std::cos(h), std::sin(h)),
                            lat(-ax.y(), ax.x());
      const double side = terrain.curb_distance(c.x(), c.y());
      for (double u : {-0.5, 0.5})
        for (double w : {-0.5, 0.5}) {
          const Eigen::Vector2d q = c + u * t.extent.x() * ax + w * t.extent.y() * lat;
          CHECK(terrain.curb_distance(q.x(), q.y()) * side > 0.0);
        }
      // The ground hits near the vehicle agree with that surface (the mesh interpolates it).
      for (std::size_t i = 0; i < s.size(); ++i) {
        const Eigen::Vector3d q =
            Eigen::Vector3d(s.xyz[3 * i], s.xyz[3 * i + 1], s.xyz[3 * i + 2]) - offset_of(o);
        if (std::abs(terrain.curb_distance(q.x(), q.y())) < 0.3) continue;  // the mesh rounds the curb
        if (s.classification[i] == 2 && (q.head<2>() - (t.center - offset_of(o)).head<2>()).norm() < 5.0)
          REQUIRE(std::abs(q.z() - terrain.height(q.x(), q.y())) < 0.01);
      }
    }
  }
}

TEST_CASE("scan-scene: two vehicles parked side by side 0.5-1 m apart; a crown over another") {
  const sh::SceneOptions o;  // defaults: 5 vehicles among clutter
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    sh::SceneOptions os = o;
    os.seed = seed;
    const sh::SceneScan s = sh::simulate_scene(fleet(), {}, os);
    REQUIRE(s.ok());
    std::vector<const sh::SceneTruth*> pair, under_tree;
    for (const sh::SceneTruth& t : s.objects) {
      if (t.flags & sh::kSideBySide) pair.push_back(&t);
      if (t.flags & sh::kUnderTree) under_tree.push_back(&t);
    }
    REQUIRE(pair.size() == 2);
    // The gap between their posed surfaces seen from above, across the first one's length.
    const double h = pair[0]->heading_deg * kPi / 180.0;
    const Eigen::Vector2d across(-std::sin(h), std::cos(h));
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < 2; ++k) {
      for (const Eigen::Vector3d& p : posed_vertices(mesh_named(pair[k]->model), pair[k]->pose)) {
        const double d = (p.head<2>() - pair[0]->center.head<2>()).dot(across);
        lo[k] = std::min(lo[k], d);
        hi[k] = std::max(hi[k], d);
      }
    }
    const double gap = std::max(lo[1] - hi[0], lo[0] - hi[1]);
    CHECK(gap >= sh::kSideBySideGapMin);
    CHECK(gap <= sh::kSideBySideGapMax);
    // Parked alongside: overlapping along their length.
    const Eigen::Vector2d along(std::cos(h), std::sin(h));
    CHECK(std::abs((pair[1]->center - pair[0]->center).head<2>().dot(along)) < 0.5 * pair[0]->extent.x());

    // Crown points lie over the footprint of a vehicle marked under a tree, higher than its roof.
    REQUIRE(!under_tree.empty());
    uint32_t most_crown_over = 0;
    for (const sh::SceneTruth* v : under_tree) {
      const double hv = v->heading_deg * kPi / 180.0;
      uint32_t crown_over = 0;
      for (std::size_t i = 0; i < s.size(); ++i) {
        const int32_t obj = s.object[i];
        if (obj < 0 || s.objects[obj].kind != sh::SceneObjectKind::kTree) continue;
        const Eigen::Vector2d d = Eigen::Vector2d(s.xyz[3 * i], s.xyz[3 * i + 1]) - v->center.head<2>();
        const bool over =
            std::abs(d.dot(Eigen::Vector2d(std::cos(hv), std::sin(hv)))) < 0.5 * v->extent.x() &&
            std::abs(d.dot(Eigen::Vector2d(-std::sin(hv), std::cos(hv)))) < 0.5 * v->extent.y();
        if (!over) continue;
        CHECK(s.xyz[3 * i + 2] > v->center.z() + v->extent.z());
        ++crown_over;
      }
      most_crown_over = std::max(most_crown_over, crown_over);
    }
    CHECK(most_crown_over > 20);
  }
}

TEST_CASE(
    "scan-scene: a tree's crown stays above the height it is asked to clear; its trunk reaches the ground") {
  sh::TerrainSpec spec;
  spec.slope_deg = 10.0;
  const sh::Terrain terrain(spec);
  sh::SeededRandom rng(5);
  for (double clear : {-double(INFINITY), 6.0, 9.5}) {
    const Eigen::Vector2d at(3.0, -2.0), crown_at(4.5, -1.0);
    const sh::PlacedObject tree = sh::make_tree(terrain, at, crown_at, clear, &rng);
    const double ground = terrain.height(at.x(), at.y());
    CHECK(tree.crown_bottom >= std::max(clear, ground + 4.0));
    CHECK(tree.crown_bottom <=
          std::max(clear, ground + 5.0 + 1.0));  // at most 5 m up, plus the slope under it
    double crown_low = INFINITY, trunk_low = INFINITY;
    for (std::size_t i = 0; i < tree.mesh.vertex_count(); ++i) {
      const Eigen::Vector3d p = tree.mesh.vertex(i);
      if ((p.head<2>() - at).norm() > 0.35) crown_low = std::min(crown_low, p.z());  // off the trunk: crown
      trunk_low = std::min(trunk_low, p.z());
    }
    CHECK(crown_low >= tree.crown_bottom - 1e-4);
    CHECK(trunk_low < ground);  // sunk into the terrain, no gap on the slope
    CHECK(tree.top - ground <= std::max(clear - ground, 5.0) + 4.0 + 0.1);  // the crown is at most 4 m deep
  }
}

TEST_CASE("scan-scene: on a steep slope crowded with trees no crown comes down onto a vehicle") {
  sh::SceneOptions o;
  o.slope_deg = 30.0;  // the ground under a vehicle can be 2 m above a tree's
  o.vehicles = 6;
  o.trees = 8;
  o.buildings = o.walls = o.crates = 0;
  o.noise_sigma = 0.0;
  uint32_t crown_points_over_vehicles = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    o.seed = seed;
    const sh::SceneScan s = sh::simulate_scene(fleet(), {}, o);
    REQUIRE_MESSAGE(s.ok(), s.error);
    for (const sh::SceneTruth& v : s.objects) {
      if (v.kind != sh::SceneObjectKind::kVehicle) continue;
      const double h = v.heading_deg * kPi / 180.0;
      const Eigen::Vector2d ax(std::cos(h), std::sin(h)), lat(-ax.y(), ax.x());
      for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.object[i] < 0 || s.objects[s.object[i]].kind != sh::SceneObjectKind::kTree) continue;
        const Eigen::Vector2d d = Eigen::Vector2d(s.xyz[3 * i], s.xyz[3 * i + 1]) - v.center.head<2>();
        if (std::abs(d.dot(ax)) > 0.5 * v.extent.x() || std::abs(d.dot(lat)) > 0.5 * v.extent.y()) continue;
        ++crown_points_over_vehicles;
        REQUIRE_MESSAGE(s.xyz[3 * i + 2] > v.center.z() + v.extent.z(), "seed " << seed << ", " << v.model);
      }
    }
  }
  CHECK(crown_points_over_vehicles > 100);
}

TEST_CASE("scan-scene: every kind is there and no two footprints intersect (crowns may overhang)") {
  sh::SceneOptions o;
  o.unknown_vehicles = 2;
  const std::vector<sh::Mesh> unknown = sh::generate_fleet(sh::kFamilyCount, 99);
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    o.seed = seed;
    const sh::SceneScan s = sh::simulate_scene(fleet(), unknown, o);
    REQUIRE(s.ok());
    uint32_t kinds[6] = {};
    for (const sh::SceneTruth& t : s.objects) ++kinds[static_cast<int>(t.kind)];
    CHECK(kinds[0] == 5);
    CHECK(kinds[1] == 2);
    CHECK(kinds[2] == 3);
    CHECK(kinds[3] == 1);
    CHECK(kinds[4] == 1);
    CHECK(kinds[5] == 3);
    for (std::size_t a = 0; a < s.objects.size(); ++a) {
      for (std::size_t b = a + 1; b < s.objects.size(); ++b) {
        const sh::SceneTruth &ta = s.objects[a], &tb = s.objects[b];
        if (ta.kind == sh::SceneObjectKind::kTree || tb.kind == sh::SceneObjectKind::kTree) continue;
        CHECK_MESSAGE(!truth_overlap(ta, tb), "seed " << seed << ": objects " << a << " and " << b);
      }
      const Eigen::Vector3d c = s.objects[a].center - offset_of(o);
      CHECK(std::max(std::abs(c.x()), std::abs(c.y())) < 0.5 * o.size);
    }
  }
}

TEST_CASE("scan-scene: vehicle-sized clutter when asked, placed after the rest, which draws as without it") {
  sh::SceneOptions plain;
  plain.size = 50.0;
  sh::SceneOptions o = plain;
  o.sheds = 1;
  o.containers = 2;
  o.bushes = 1;
  o.heaps = 1;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    o.seed = plain.seed = seed;
    const sh::SceneScan s = sh::simulate_scene(fleet(), {}, o), p = sh::simulate_scene(fleet(), {}, plain);
    REQUIRE(s.ok());
    REQUIRE(p.ok());
    uint32_t kinds[10] = {};
    for (const sh::SceneTruth& t : s.objects) ++kinds[static_cast<int>(t.kind)];
    CHECK(kinds[static_cast<int>(sh::SceneObjectKind::kShed)] == 1);
    CHECK(kinds[static_cast<int>(sh::SceneObjectKind::kContainer)] == 2);
    CHECK(kinds[static_cast<int>(sh::SceneObjectKind::kBush)] == 1);
    CHECK(kinds[static_cast<int>(sh::SceneObjectKind::kHeap)] == 1);
    REQUIRE(s.objects.size() == p.objects.size() + 5u);
    for (std::size_t a = 0; a < s.objects.size(); ++a) {
      if (a < p.objects.size()) {  // the same layout before them (hits differ: they shadow some)
        CHECK(s.objects[a].kind == p.objects[a].kind);
        CHECK(s.objects[a].pose.isApprox(p.objects[a].pose));
      }
      for (std::size_t b = a + 1; b < s.objects.size(); ++b) {
        const sh::SceneTruth &ta = s.objects[a], &tb = s.objects[b];
        if (ta.kind == sh::SceneObjectKind::kTree || tb.kind == sh::SceneObjectKind::kTree) continue;
        CHECK_MESSAGE(!truth_overlap(ta, tb), "seed " << seed << ": objects " << a << " and " << b);
      }
    }
    for (std::size_t a = p.objects.size(); a < s.objects.size(); ++a) CHECK(s.objects[a].points > 0u);
  }
  o.containers = sh::kMaxSceneClutter + 1u;
  CHECK(sh::validate_scene_options(o).find("containers") != std::string::npos);
}

TEST_CASE("scan-scene: the same seed gives the same tile; another seed another") {
  sh::SceneOptions o;
  o.size = 30.0;
  o.buildings = 0;
  o.vehicles = 3;
  const sh::SceneScan a = sh::simulate_scene(fleet(), {}, o), b = sh::simulate_scene(fleet(), {}, o);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a.xyz == b.xyz);
  CHECK(a.classification == b.classification);
  CHECK(sh::scene_truth_csv(a.objects) == sh::scene_truth_csv(b.objects));
  o.seed = 2;
  const sh::SceneScan c = sh::simulate_scene(fleet(), {}, o);
  REQUIRE(c.ok());
  CHECK(a.xyz != c.xyz);
  CHECK(sh::scene_truth_csv(a.objects) != sh::scene_truth_csv(c.objects));
}

TEST_CASE("scan-scene: rays are bounded; a tile too large for the spacing is refused, not truncated") {
  sh::SceneOptions o = bare_options(0.0);
  o.vehicles = 0;
  const sh::SceneScan ok = sh::simulate_scene({}, {}, o);
  REQUIRE(ok.ok());
  CHECK(ok.rays > 0);
  CHECK(ok.rays <= sh::kMaxRaysPerScan);
  o.size = 120.0;
  o.point_spacing = 0.02;  // ~9M rays per view
  const sh::SceneScan big = sh::simulate_scene({}, {}, o);
  CHECK_FALSE(big.ok());
  CHECK(contains(big.error, "too many rays"));
  CHECK(contains(big.error, std::to_string(sh::kMaxRaysPerView)));
  CHECK(big.xyz.empty());
}

TEST_CASE("scan-scene: bad layouts and meshes are errors with a message") {
  sh::SceneOptions o;
  o.size = 12.0;  // no room for a 10-15 m building
  sh::SceneScan s = sh::simulate_scene(fleet(), {}, o);
  CHECK_FALSE(s.ok());
  CHECK(contains(s.error, "cannot place building"));
  o = sh::SceneOptions{};
  s = sh::simulate_scene({}, {}, o);
  CHECK(contains(s.error, "no vehicle meshes"));
  o.unknown_vehicles = 1;
  s = sh::simulate_scene(fleet(), {}, o);
  CHECK(contains(s.error, "no unknown-vehicle meshes"));
  o = sh::SceneOptions{};
  o.point_spacing = 0.0;
  CHECK(contains(sh::simulate_scene(fleet(), {}, o).error, "point spacing"));
  o = sh::SceneOptions{};
  o.size = 0.0;
  CHECK(contains(sh::simulate_scene(fleet(), {}, o).error, "tile size"));
  std::vector<sh::Mesh> bad = fleet();
  bad[2].vertices[0] = NAN;
  CHECK(contains(sh::simulate_scene(bad, {}, sh::SceneOptions{}).error, "vehicle mesh"));
}

TEST_CASE("spinhash scan-scene: LAS with ground classified 2 and a truth CSV; bad options exit 2 or 1") {
  TempDir dir("scan-scene");
  const std::string meshes = dir.file("meshes");
  std::filesystem::create_directories(meshes);
  for (std::size_t i = 0; i < 4; ++i) {
    std::string error;
    REQUIRE(sh::write_mesh(meshes + "/" + fleet()[i].name + ".obj", fleet()[i], &error));
  }
  const std::string las = dir.file("tile.las"), truth = dir.file("truth.csv");
  auto r = run_spinhash(dir, "scan-scene " + shell_quoted(meshes) + " -o " + shell_quoted(las) + " --truth " +
                                 shell_quoted(truth) + " --slope 5 --seed 3");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  sh::LasCloud cloud;
  std::string error;
  REQUIRE(sh::parse_las(spinhash::host::test::read_bytes(las), &cloud, &error));
  CHECK(cloud.header.scale[0] == doctest::Approx(0.001));
  const std::size_t n = cloud.classification.size();
  REQUIRE(n > 100000);
  const std::size_t ground = std::count(cloud.classification.begin(), cloud.classification.end(), 2);
  CHECK(ground > n / 2);
  CHECK(std::count(cloud.classification.begin(), cloud.classification.end(), 1) > 10000);  // the objects
  CHECK(ground + std::count(cloud.classification.begin(), cloud.classification.end(), 1) == n);
  CHECK(std::abs(cloud.xyz[0] - 512000.0) < 21.0);
  CHECK(std::abs(cloud.xyz[1] - 5400000.0) < 21.0);
  const std::string csv = spinhash::host::test::read_bytes(truth);
  CHECK(csv.rfind("kind,model,center_x", 0) == 0);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 5 + 3 + 1 + 1 + 3);
  for (const char* kind : {"\nvehicle,", "\ntree,", "\nbuilding,", "\nwall,", "\ncrate,"})
    CHECK(contains(csv, kind));
  CHECK_FALSE(contains(csv, "\ncontainer,"));  // vehicle-sized clutter only when asked
  r = run_spinhash(dir, "scan-scene " + shell_quoted(meshes) + " -o " + shell_quoted(dir.file("sized.las")) +
                            " --size 50 --sheds 1 --containers 1 --bushes 1 --heaps 1 --seed 3");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::string sized = spinhash::host::test::read_bytes(dir.file("sized.las.truth.csv"));
  for (const char* kind : {"\nshed,", "\ncontainer,", "\nbush,", "\nheap,"}) CHECK(contains(sized, kind));
  r = run_spinhash(dir, "scan-scene " + shell_quoted(meshes) + " -o " + shell_quoted(las) + " --heaps 65");
  CHECK(r.exit_code == 2);
  CHECK(contains(r.err, "heaps"));

  r = run_spinhash(dir, "scan-scene " + shell_quoted(meshes) + " -o " + shell_quoted(las) + " --size 0");
  CHECK(r.exit_code == 2);
  CHECK(contains(r.err, "size"));
  r = run_spinhash(dir, "scan-scene " + shell_quoted(meshes) + " -o " + shell_quoted(las) + " --spacing 0");
  CHECK(r.exit_code == 2);
  CHECK(contains(r.err, "spacing"));
  r = run_spinhash(dir, "scan-scene -o " + shell_quoted(las));
  CHECK(r.exit_code == 2);
  CHECK(contains(r.err, "meshes"));
  std::filesystem::create_directories(dir.file("empty"));
  r = run_spinhash(dir, "scan-scene " + shell_quoted(dir.file("empty")) + " -o " + shell_quoted(las));
  CHECK(r.exit_code == 1);
  CHECK(contains(r.err, "spinhash scan-scene: "));
  spinhash::host::test::write_bytes(dir.file("broken.obj"), "v 0 0 0\nf 1 2 9\nthis is not a mesh\n");
  r = run_spinhash(dir, "scan-scene " + shell_quoted(dir.file("broken.obj")) + " -o " + shell_quoted(las));
  CHECK(r.exit_code == 1);
  CHECK(contains(r.err, "broken.obj"));
  r = run_spinhash(
      dir, "scan-scene " + shell_quoted(meshes) + " -o " + shell_quoted(las) + " --unknown-vehicles 1");
  CHECK(r.exit_code == 1);
  CHECK(contains(r.err, "--unknown"));
  r = run_spinhash(dir, "scan-scene " + shell_quoted(meshes) + " -o " + shell_quoted(dir.file("t.xyz")));
  CHECK(r.exit_code == 1);
  CHECK(contains(r.err, "extension"));
}
