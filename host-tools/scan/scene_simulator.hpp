// The tile simulator (`spinhash scan-scene`): one scene mesh, terrain plus
// vehicles resting on it plus clutter, ray-cast from several oblique
// airborne viewpoints into a georeferenced cloud with its truth.
//
// Frames: the scene is built and cast in a tile-local frame (tile centre at
// x = y = 0, z up) so the float ray caster stays precise; points, poses and
// centres are returned georeferenced (local + offset, in double).
#pragma once

#include "mesh/mesh.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

constexpr double kMaxSceneSize = 500.0;       // m, tile side
constexpr uint32_t kMaxSceneVehicles = 64;    // vehicles and unknown vehicles, each
constexpr uint32_t kMaxSceneClutter = 64;     // of each kind of non-vehicle
constexpr double kMaxSceneSlopeDeg = 30.0;    // terrain plane
constexpr double kSceneElevationMinDeg = 45;  // viewpoints: elevation drawn in [min, max]
constexpr double kSceneElevationMaxDeg = 60;
constexpr double kSceneRangeMin = 100.0;  // m: sensor to the tile centre, drawn in [min, max]
constexpr double kSceneRangeMax = 200.0;
constexpr uint32_t kMaxPlacementAttempts = 1000;  // per object: then the layout fails with a message
constexpr double kSideBySideGapMin = 0.5;         // m between the parked pair's footprints
constexpr double kSideBySideGapMax = 1.0;

struct SceneOptions {
  double size = 40.0;               // m, side of the square tile
  double slope_deg = 8.0;           // terrain plane, random direction
  double slope_azimuth_deg = -1.0;  // the plane's rising direction from +x (< 0: random)
  double bump_height = 0.3;         // m, largest bump (0: none)
  double curb_height = 0.15;
  uint32_t vehicles = 5;  // from the database meshes; the first two side by side, the last under a tree
  uint32_t parked_rows =
      0;  // rows of row_length vehicles parked side by side (of `vehicles`, after the pair)
  uint32_t row_length = 4;
  uint32_t unknown_vehicles = 0;  // from the unknown meshes
  uint32_t trees = 3;             // one of them over a vehicle
  uint32_t buildings = 1;
  uint32_t walls = 1;
  uint32_t crates = 3;
  // Non-vehicles of a vehicle's size and bulk, none unless asked for: the
  // hardest for the vehicle level (a freight container is a bus's box).
  uint32_t sheds = 0;
  uint32_t containers = 0;
  uint32_t bushes = 0;
  uint32_t heaps = 0;
  uint32_t views = 4;
  // Point spacing on the ground of the merged views (m): each view's rays are
  // spaced so that `views` views together give 1 / spacing^2 points per m^2
  // of level ground.
  double point_spacing = 0.10;
  double noise_sigma = 0.05;  // m, Gaussian along each ray
  uint64_t seed = 1;
  double offset[3] = {512000.0, 5400000.0, 300.0};  // added to every output coordinate (UTM-like)
};

// Tiles hold vehicles, trees, buildings, walls and crates, and when asked
// sheds, freight containers, bushes and heaps: non-vehicles of a vehicle's
// size (the worlds experiment also scans them alone).
enum class SceneObjectKind : uint8_t {
  kVehicle,
  kUnknownVehicle,
  kTree,
  kBuilding,
  kWall,
  kCrate,
  kShed,
  kContainer,
  kBush,
  kHeap,
};
const char* scene_object_kind_name(SceneObjectKind kind);

// Situations of a vehicle that make it hard (bits of SceneTruth::flags).
constexpr uint32_t kSideBySide = 1u;  // parked beside another, 0.5-1 m apart
constexpr uint32_t kUnderTree = 2u;   // a crown overhangs it

struct SceneTruth {
  SceneObjectKind kind = SceneObjectKind::kCrate;
  std::string model;  // mesh name for vehicles; empty otherwise
  // Model (or the clutter's own frame: footprint centre, z at its base) ->
  // georeferenced tile frame.
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // footprint centre; z on the terrain there
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();  // length, width (along heading), height above center z
  double heading_deg = 0.0;                          // length axis, degrees from +x
  uint32_t flags = 0;
  uint32_t points = 0;  // hits on it
};

struct SceneScan {
  std::vector<double> xyz;              // georeferenced x y z per point
  std::vector<uint8_t> classification;  // per point: 2 terrain, 1 anything else (ASPRS)
  std::vector<int32_t> object;          // per point: index into objects, -1 terrain
  std::vector<SceneTruth> objects;
  std::vector<Eigen::Vector3d> viewpoints;  // georeferenced sensor positions
  std::vector<uint32_t> view_points;        // points from each view
  uint64_t rays = 0;                        // cast in all
  std::string error;                        // empty on success
  bool ok() const { return error.empty(); }
  std::size_t size() const { return xyz.size() / 3; }
};

// Empty string if the options are usable; else what is wrong.
std::string validate_scene_options(const SceneOptions& options);

// vehicles: meshes of the database (x forward, z up, resting at their lowest
// z); unknown: meshes not in it (may be empty when unknown_vehicles is 0).
// Deterministic for options.seed. On failure only `error` is set.
SceneScan simulate_scene(const std::vector<Mesh>& vehicles, const std::vector<Mesh>& unknown,
                         const SceneOptions& options);

// The truth as CSV: a header line, then per object kind, model, centre
// (x y z), extent (3), heading, flags, points and the 16 pose numbers row by
// row. Written atomically; false with *error.
bool write_scene_truth(const std::string& path, const std::vector<SceneTruth>& objects, std::string* error);
std::string scene_truth_csv(const std::vector<SceneTruth>& objects);

}  // namespace spinhash::host
