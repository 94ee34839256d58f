#include "scan/scene_simulator.hpp"

#include "mesh/seeded_random.hpp"
#include "scan/ray_caster.hpp"
#include "scan/ray_grid.hpp"
#include "scan/scan_simulator.hpp"
#include "scan/scene_layout.hpp"
#include "scan/scene_terrain.hpp"
#include "util/angles.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

namespace spinhash::host {
namespace {

constexpr uint64_t kViewStream = 0x7300;
constexpr uint64_t kNoiseStream = 0x7301;
constexpr uint8_t kGroundClass = 2, kOtherClass = 1;  // ASPRS
constexpr int32_t kTerrainGeometry = 0;               // objects follow: geometry k + 1 is object k
// The sensor stays at least this many scene radii away (tiles wider than
// the ranges above), so the grid's half angle stays below 30 degrees.
constexpr double kMinRangeOverRadius = 2.0;
constexpr double kMaxSpacing = 10.0;  // m
constexpr double kMaxNoiseSigma = 10.0;

std::string check_meshes(const std::vector<Mesh>& meshes, const char* what) {
  for (const Mesh& m : meshes) {
    std::string e = m.validate();
    if (e.empty() && m.triangle_count() == 0) e = "no triangles";
    if (!e.empty()) return std::string(what) + " mesh '" + m.name + "': " + e;
  }
  return {};
}

// Farthest vertex of the scene from `target`.
double scene_radius(const Mesh& terrain, const std::vector<PlacedObject>& objects,
                    const Eigen::Vector3d& target) {
  double r = 0.0;
  auto grow = [&](const Mesh& m) {
    for (std::size_t i = 0; i < m.vertex_count(); ++i) r = std::max(r, (m.vertex(i) - target).norm());
  };
  grow(terrain);
  for (const PlacedObject& p : objects) grow(p.mesh);
  return r;
}

SceneScan run_scene(const std::vector<Mesh>& vehicles, const std::vector<Mesh>& unknown,
                    const SceneOptions& o) {
  SceneScan out;
  out.error = validate_scene_options(o);
  if (out.error.empty() && o.vehicles > 0 && vehicles.empty()) out.error = "no vehicle meshes given";
  if (out.error.empty() && o.unknown_vehicles > 0 && unknown.empty())
    out.error = "no unknown-vehicle meshes given";
  if (out.error.empty()) out.error = check_meshes(vehicles, "vehicle");
  if (out.error.empty()) out.error = check_meshes(unknown, "unknown-vehicle");
  if (!out.error.empty()) return out;

  TerrainSpec spec;
  spec.size = o.size;
  spec.slope_deg = o.slope_deg;
  spec.slope_azimuth_deg = o.slope_azimuth_deg;
  spec.bump_height = o.bump_height;
  spec.curb_height = o.curb_height;
  spec.seed = o.seed;
  const Terrain terrain(spec);
  std::vector<PlacedObject> objects;
  if (!lay_out_scene(vehicles, unknown, o, terrain, &objects, &out.error)) return out;

  const Mesh ground = terrain.mesh();
  RayCaster caster;
  if (!caster.add_mesh(ground, Eigen::Vector3d::Zero(), &out.error)) return out;
  for (const PlacedObject& p : objects) {
    if (!caster.add_mesh(p.mesh, Eigen::Vector3d::Zero(), &out.error)) return out;
  }
  if (!caster.commit(&out.error)) return out;

  // Every view aims at the tile centre on the ground.
  const Eigen::Vector3d target(0.0, 0.0, terrain.height(0.0, 0.0));
  const double radius = scene_radius(ground, objects, target);
  SeededRandom view_rng(mix_seed(o.seed, kViewStream));
  SeededRandom noise(mix_seed(o.seed, kNoiseStream));
  const double azimuth0 = view_rng.uniform(0.0, 2.0 * kPi);
  std::vector<double> xyz;
  std::vector<int32_t> geometry;
  for (uint32_t v = 0; v < o.views; ++v) {
    const double azimuth = azimuth0 + 2.0 * kPi * v / o.views;
    const double elevation = view_rng.uniform(kSceneElevationMinDeg, kSceneElevationMaxDeg) * kDegToRad;
    const double range =
        std::max(view_rng.uniform(kSceneRangeMin, kSceneRangeMax), kMinRangeOverRadius * radius);
    // Rays spaced so the views together give 1 / spacing^2 points per m^2 of level ground.
    const double spacing = o.point_spacing * std::sqrt(o.views * std::sin(elevation));
    RayGrid grid;
    std::string why;
    if (!plan_ray_grid(std::asin(radius / range), spacing / range, o.views, &grid, &why)) {
      out.error = "point spacing " + std::to_string(o.point_spacing) + " m over a " + std::to_string(o.size) +
                  " m tile needs too many rays: " + why;
      return out;
    }
    View view = make_view(azimuth, elevation, range);
    view.origin += target;
    const int64_t hits = cast_view(caster, view, grid, o.noise_sigma, &noise, &xyz, &geometry, &out.error);
    if (hits < 0) return out;
    out.rays += grid.rays();
    out.view_points.push_back(static_cast<uint32_t>(hits));
    out.viewpoints.push_back(view.origin);
  }

  const Eigen::Vector3d offset(o.offset[0], o.offset[1], o.offset[2]);
  const std::size_t n = geometry.size();
  out.classification.resize(n);
  out.object.resize(n);
  for (const PlacedObject& p : objects) out.objects.push_back(p.truth);
  for (std::size_t i = 0; i < n; ++i) {
    const int32_t object = geometry[i] - 1;
    out.classification[i] = geometry[i] == kTerrainGeometry ? kGroundClass : kOtherClass;
    out.object[i] = object;
    if (object >= 0) ++out.objects[object].points;
    for (int k = 0; k < 3; ++k) xyz[3 * i + k] += offset[k];
  }
  out.xyz = std::move(xyz);
  for (Eigen::Vector3d& p : out.viewpoints) p += offset;
  for (SceneTruth& t : out.objects) {
    t.pose.topRightCorner<3, 1>() += offset;
    t.center += offset;
  }
  return out;
}

}  // namespace

const char* scene_object_kind_name(SceneObjectKind kind) {
  switch (kind) {
    case SceneObjectKind::kVehicle: return "vehicle";
    case SceneObjectKind::kUnknownVehicle: return "unknown_vehicle";
    case SceneObjectKind::kTree: return "tree";
    case SceneObjectKind::kBuilding: return "building";
    case SceneObjectKind::kWall: return "wall";
    case SceneObjectKind::kCrate: return "crate";
    case SceneObjectKind::kShed: return "shed";
    case SceneObjectKind::kContainer: return "container";
    case SceneObjectKind::kBush: return "bush";
    case SceneObjectKind::kHeap: return "heap";
  }
  return "?";
}

std::string validate_scene_options(const SceneOptions& o) {
  if (!(o.size > 0.0 && o.size <= kMaxSceneSize))
    return "tile size must be in (0, " + std::to_string(static_cast<int>(kMaxSceneSize)) + "] m";
  if (!(o.slope_deg >= 0.0 && o.slope_deg <= kMaxSceneSlopeDeg))
    return "slope must be in [0, " + std::to_string(static_cast<int>(kMaxSceneSlopeDeg)) + "] degrees";
  if (!(o.bump_height >= 0.0 && o.bump_height <= 0.1 * o.size))
    return "bump height must be in [0, size / 10] m";
  if (!(o.curb_height >= 0.0 && o.curb_height <= 1.0)) return "curb height must be in [0, 1] m";
  if (o.vehicles > kMaxSceneVehicles || o.unknown_vehicles > kMaxSceneVehicles)
    return "at most " + std::to_string(kMaxSceneVehicles) + " vehicles and unknown vehicles each";
  for (const uint32_t n : {o.trees, o.buildings, o.walls, o.crates, o.sheds, o.containers, o.bushes, o.heaps})
    if (n > kMaxSceneClutter)
      return "at most " + std::to_string(kMaxSceneClutter) +
             " trees, buildings, walls, crates, sheds, containers, bushes and heaps each";
  if (o.views == 0 || o.views > kMaxScanViews) return "views must be in 1.." + std::to_string(kMaxScanViews);
  if (!(o.point_spacing > 0.0 && o.point_spacing <= kMaxSpacing)) return "point spacing must be in (0, 10] m";
  if (!(o.noise_sigma >= 0.0 && o.noise_sigma <= kMaxNoiseSigma)) return "noise sigma must be in [0, 10] m";
  for (double v : o.offset) {
    if (!std::isfinite(v)) return "offset must be finite";
  }
  return {};
}

SceneScan simulate_scene(const std::vector<Mesh>& vehicles, const std::vector<Mesh>& unknown,
                         const SceneOptions& options) {
  SceneScan result;
  try {
    result = run_scene(vehicles, unknown, options);
  } catch (const std::exception& e) {
    result.error = std::string("scene simulation failed: ") + e.what();
  }
  if (!result.ok()) {
    const std::string error = result.error;  // no partial tiles: only the error
    result = SceneScan{};
    result.error = error;
  }
  return result;
}

}  // namespace spinhash::host
