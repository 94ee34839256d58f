// The simulator's non-vehicles: buildings, walls, crates and trees, which
// tiles hold, and ones of a vehicle's size and bulk (sheds, freight
// containers, bushes, heaps), the hardest for the vehicle level, which the
// worlds experiment scans alone. Each is built in its own frame (footprint
// centre, z = 0 at its base), then posed on the terrain; bases are sunk
// below the lowest ground under them so no gap shows on a slope.
#include "mesh/vehicle_parts.hpp"
#include "scan/scene_layout.hpp"
#include "util/angles.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace spinhash::host {
namespace {

constexpr uint32_t kTerrainSamples = 7;   // per side of a footprint, for its lowest and highest ground
constexpr double kFoundationDepth = 0.3;  // m below the lowest ground
// Building (m): footprint side, eaves above the highest ground, roof rise.
constexpr double kBuildingSideMin = 10.0, kBuildingSideMax = 15.0;
constexpr double kEavesMin = 4.0, kEavesMax = 6.0;
constexpr double kRoofRiseMin = 1.5, kRoofRiseMax = 3.0;
// Wall (m).
constexpr double kWallLength = 14.0, kWallThickness = 0.25;
constexpr double kWallHeightMin = 2.0, kWallHeightMax = 3.0;
// Crate (m).
constexpr double kCrateSideMin = 0.8, kCrateSideMax = 1.2;
constexpr double kCrateHeightMin = 0.7, kCrateHeightMax = 1.1;
// Tree (m): trunk, crown underside above the ground at the trunk, crown depth
// and radius; the crown is a few flattened blobs, porous like foliage.
constexpr double kTrunkRadiusMin = 0.15, kTrunkRadiusMax = 0.3;
constexpr uint32_t kTrunkSegments = 10;
constexpr double kCrownBottomMin = 4.0, kCrownBottomMax = 5.0;
constexpr double kCrownDepthMin = 3.0, kCrownDepthMax = 4.0;
constexpr double kCrownRadiusMin = 2.5, kCrownRadiusMax = 3.5;
constexpr uint32_t kCrownBlobs = 8;
constexpr double kBlobRadiusMin = 0.9, kBlobRadiusMax = 1.4;
constexpr double kBlobFlatten = 0.7;  // vertical / horizontal radius
constexpr double kBlobSpread = 0.6;   // of the crown radius: blob centres within it
constexpr uint32_t kBlobSlices = 10, kBlobStacks = 6;
// Plan and height ranges (m) of a drawn object; the width never exceeds the length.
struct SizeRanges {
  double length_min, length_max, width_min, width_max, height_min, height_max;
};
// Shed or single garage: from a garden shed's 2.4 x 1.8 m to a garage's
// 6.5 x 3.6 m, eaves (its height) at a door's height and more, a gable
// from nearly flat.
constexpr SizeRanges kShed{2.4, 6.5, 1.8, 3.6, 2.0, 2.7};
constexpr double kShedRoofRiseMin = 0.1, kShedRoofRiseMax = 1.2;
// Freight container, ISO 668 series 1 (m): 20 ft or 40 ft long, 8 ft wide,
// 8 ft 6 in tall or 9 ft 6 in (high cube).
constexpr double kContainerLengths[] = {6.058, 12.192};
constexpr double kContainerWidth = 2.438;
constexpr double kContainerHeights[] = {2.591, 2.896};
// Bush or hedge: foliage blobs in a row, about one per kBushBlobPitch (m).
constexpr SizeRanges kBush{1.5, 6.0, 1.0, 2.5, 0.8, 2.2};
constexpr double kBushBlobPitch = 1.2;
constexpr double kBushBlobJitter = 0.15;  // of a blob's radii, drawn per blob
// Heap of earth, gravel or a covered load: half an ellipsoid.
constexpr SizeRanges kHeap{2.5, 8.0, 2.0, 5.0, 0.8, 2.5};

struct GroundRange {
  double lo = 0.0, hi = 0.0;
};

GroundRange ground_under(const Terrain& t, const Footprint& f) {
  GroundRange r{INFINITY, -INFINITY};
  for (uint32_t j = 0; j < kTerrainSamples; ++j) {
    for (uint32_t i = 0; i < kTerrainSamples; ++i) {
      const double u = (2.0 * i / (kTerrainSamples - 1) - 1.0) * f.half.x();
      const double v = (2.0 * j / (kTerrainSamples - 1) - 1.0) * f.half.y();
      const Eigen::Vector2d p = f.center + u * f.axis() + v * f.lateral();
      const double z = t.height(p.x(), p.y());
      r.lo = std::min(r.lo, z);
      r.hi = std::max(r.hi, z);
    }
  }
  return r;
}

// Pose of an object's own frame: turned by yaw, its base at (at, base_z).
Eigen::Matrix4d frame_pose(const Eigen::Vector2d& at, double base_z, double yaw) {
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  pose.topLeftCorner<3, 3>() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.topRightCorner<3, 1>() = Eigen::Vector3d(at.x(), at.y(), base_z);
  return pose;
}

// Poses the object's mesh and fills its truth from its footprint.
PlacedObject finish(SceneObjectKind kind, Mesh mesh, const Eigen::Matrix4d& pose, const Footprint& base,
                    const Terrain& t) {
  PlacedObject p;
  mesh.apply_transform(pose);
  p.mesh = std::move(mesh);
  p.base = base;
  p.top = p.mesh.bounding_box().hi.z();
  p.truth.kind = kind;
  p.truth.pose = pose;
  const double ground = t.height(base.center.x(), base.center.y());
  p.truth.center = Eigen::Vector3d(base.center.x(), base.center.y(), ground);
  p.truth.extent = Eigen::Vector3d(2.0 * base.half.x(), 2.0 * base.half.y(), p.top - ground);
  p.truth.heading_deg = base.heading * kRadToDeg;
  return p;
}

Footprint rectangle(const Eigen::Vector2d& at, double length, double width, double yaw) {
  Footprint f;
  f.center = at;
  f.half = Eigen::Vector2d(0.5 * length, 0.5 * width);
  f.heading = yaw;
  return f;
}

// An object's size drawn from its ranges (length, width, height, in that
// order), its footprint at `at` and the ground under it.
struct Drawn {
  double length = 0.0, width = 0.0, height = 0.0;
  Footprint base;
  GroundRange ground;
};

Drawn draw_size(const Terrain& t, const Eigen::Vector2d& at, double yaw, const SizeRanges& r,
                SeededRandom* rng) {
  Drawn d;
  d.length = rng->uniform(r.length_min, r.length_max);
  d.width = rng->uniform(r.width_min, std::min(r.width_max, d.length));
  d.height = rng->uniform(r.height_min, r.height_max);
  d.base = rectangle(at, d.length, d.width, yaw);
  d.ground = ground_under(t, d.base);
  return d;
}

// Closed ellipsoid of kBlobSlices x kBlobStacks quads.
void add_ellipsoid(Mesh* mesh, const Eigen::Vector3d& c, const Eigen::Vector3d& radii) {
  const uint32_t first = static_cast<uint32_t>(mesh->vertex_count());
  mesh->add_vertex(c - Eigen::Vector3d(0, 0, radii.z()));
  for (uint32_t s = 1; s < kBlobStacks; ++s) {
    const double phi = kPi * s / kBlobStacks - 0.5 * kPi;
    for (uint32_t k = 0; k < kBlobSlices; ++k) {
      const double theta = 2.0 * kPi * k / kBlobSlices;
      mesh->add_vertex(c + Eigen::Vector3d(radii.x() * std::cos(phi) * std::cos(theta),
                                           radii.y() * std::cos(phi) * std::sin(theta),
                                           radii.z() * std::sin(phi)));
    }
  }
  const uint32_t top = mesh->add_vertex(c + Eigen::Vector3d(0, 0, radii.z()));
  auto ring = [&](uint32_t s, uint32_t k) { return first + 1 + (s - 1) * kBlobSlices + k % kBlobSlices; };
  for (uint32_t k = 0; k < kBlobSlices; ++k) {
    mesh->add_triangle(first, ring(1, k + 1), ring(1, k));
    mesh->add_triangle(top, ring(kBlobStacks - 1, k), ring(kBlobStacks - 1, k + 1));
    for (uint32_t s = 1; s + 1 < kBlobStacks; ++s) {
      mesh->add_triangle(ring(s, k), ring(s, k + 1), ring(s + 1, k + 1));
      mesh->add_triangle(ring(s, k), ring(s + 1, k + 1), ring(s + 1, k));
    }
  }
}

// A box standing on the terrain (its base sunk to the lowest ground under
// it), its top `height_min..max` above the highest.
PlacedObject box_on_ground(SceneObjectKind kind, const char* name, const Terrain& t,
                           const Eigen::Vector2d& at, double yaw, double length, double width,
                           double height_min, double height_max, SeededRandom* rng) {
  const Footprint base = rectangle(at, length, width, yaw);
  const GroundRange g = ground_under(t, base);
  const double base_z = g.lo - kFoundationDepth;
  const double top = g.hi + rng->uniform(height_min, height_max) - base_z;
  Mesh m;
  m.name = name;
  add_box(&m, {-0.5 * length, -0.5 * width, 0.0}, {0.5 * length, 0.5 * width, top});
  return finish(kind, std::move(m), frame_pose(at, base_z, yaw), base, t);
}

// A box with a gable roof along its length, standing on the terrain: eaves
// `eaves_height` above the highest ground under it, the ridge
// rise_min..max above the eaves.
PlacedObject gabled_box(SceneObjectKind kind, const char* name, const Terrain& t, const Eigen::Vector2d& at,
                        double yaw, double length, double width, double eaves_height, double rise_min,
                        double rise_max, SeededRandom* rng) {
  const Footprint base = rectangle(at, length, width, yaw);
  const GroundRange g = ground_under(t, base);
  const double base_z = g.lo - kFoundationDepth;
  const double eaves = g.hi + eaves_height - base_z;
  const double ridge = eaves + rng->uniform(rise_min, rise_max);
  Mesh m;
  m.name = name;
  const double hl = 0.5 * length, hw = 0.5 * width;
  add_box(&m, {-hl, -hw, 0.0}, {hl, hw, eaves});
  // Gable roof: a triangular prism along the length.
  add_loft(&m, {{-hl, -hw, eaves}, {-hl, hw, eaves}, {-hl, 0.0, ridge}},
           {{hl, -hw, eaves}, {hl, hw, eaves}, {hl, 0.0, ridge}});
  return finish(kind, std::move(m), frame_pose(at, base_z, yaw), base, t);
}

}  // namespace

PlacedObject make_building(const Terrain& t, const Eigen::Vector2d& at, double yaw, SeededRandom* rng) {
  const double length = rng->uniform(kBuildingSideMin, kBuildingSideMax);
  const double width = rng->uniform(kBuildingSideMin, kBuildingSideMax);
  const double eaves = rng->uniform(kEavesMin, kEavesMax);
  return gabled_box(SceneObjectKind::kBuilding, "building", t, at, yaw, length, width, eaves, kRoofRiseMin,
                    kRoofRiseMax, rng);
}

PlacedObject make_wall(const Terrain& t, const Eigen::Vector2d& at, double yaw, SeededRandom* rng) {
  return box_on_ground(SceneObjectKind::kWall, "wall", t, at, yaw, kWallLength, kWallThickness,
                       kWallHeightMin, kWallHeightMax, rng);
}

PlacedObject make_crate(const Terrain& t, const Eigen::Vector2d& at, double yaw, SeededRandom* rng) {
  const double length = rng->uniform(kCrateSideMin, kCrateSideMax);
  const double width = rng->uniform(kCrateSideMin, kCrateSideMax);
  return box_on_ground(SceneObjectKind::kCrate, "crate", t, at, yaw, length, width, kCrateHeightMin,
                       kCrateHeightMax, rng);
}

PlacedObject make_tree(const Terrain& t, const Eigen::Vector2d& at, const Eigen::Vector2d& crown_at,
                       double min_crown_bottom, SeededRandom* rng) {
  const double trunk_r = rng->uniform(kTrunkRadiusMin, kTrunkRadiusMax);
  const double crown_r = rng->uniform(kCrownRadiusMin, kCrownRadiusMax);
  const Footprint base = rectangle(at, 2.0 * trunk_r, 2.0 * trunk_r, 0.0);
  const GroundRange g = ground_under(t, base);
  const double base_z = g.lo - kFoundationDepth;
  const double bottom = std::max(g.hi + rng->uniform(kCrownBottomMin, kCrownBottomMax), min_crown_bottom);
  const double depth = rng->uniform(kCrownDepthMin, kCrownDepthMax);
  Mesh m;
  m.name = "tree";
  // In the tree's frame (trunk axis at x = y = 0, z from base_z).
  const double trunk_top = bottom + 0.5 * depth - base_z;
  add_cylinder(&m, {0.0, 0.0, 0.5 * trunk_top}, Axis::kZ, trunk_r, trunk_top, kTrunkSegments);
  const Eigen::Vector2d crown_c = crown_at - at;
  for (uint32_t b = 0; b < kCrownBlobs; ++b) {
    const double r = rng->uniform(kBlobRadiusMin, kBlobRadiusMax);
    const double rz = kBlobFlatten * r;
    const double a = rng->uniform(0.0, 2.0 * kPi), d = kBlobSpread * crown_r * std::sqrt(rng->uniform01());
    const double z = rng->uniform(bottom + rz, std::max(bottom + rz, bottom + depth - rz)) - base_z;
    add_ellipsoid(&m, {crown_c.x() + d * std::cos(a), crown_c.y() + d * std::sin(a), z}, {r, r, rz});
  }
  const Eigen::Matrix4d pose = frame_pose(at, base_z, 0.0);
  PlacedObject p = finish(SceneObjectKind::kTree, std::move(m), pose, base, t);
  p.has_crown = true;
  p.crown = footprint_of(p.mesh, 0.0);
  p.crown_bottom = bottom;
  p.truth.extent.head<2>() = 2.0 * p.crown.half;  // the crown's spread
  return p;
}

PlacedObject make_shed(const Terrain& t, const Eigen::Vector2d& at, double yaw, SeededRandom* rng) {
  const Drawn d = draw_size(t, at, yaw, kShed, rng);
  return gabled_box(SceneObjectKind::kShed, "shed", t, at, yaw, d.length, d.width, d.height, kShedRoofRiseMin,
                    kShedRoofRiseMax, rng);
}

PlacedObject make_container(const Terrain& t, const Eigen::Vector2d& at, double yaw, SeededRandom* rng) {
  const double length = kContainerLengths[rng->below(2u)];
  const double height = kContainerHeights[rng->below(2u)];
  return box_on_ground(SceneObjectKind::kContainer, "container", t, at, yaw, length, kContainerWidth, height,
                       height, rng);
}

PlacedObject make_bush(const Terrain& t, const Eigen::Vector2d& at, double yaw, SeededRandom* rng) {
  const Drawn d = draw_size(t, at, yaw, kBush, rng);
  const double base_z = d.ground.lo - kFoundationDepth;
  const double ground = d.ground.hi - base_z;  // the highest ground, in the bush's frame
  const uint32_t blobs = std::max(2u, static_cast<uint32_t>(std::lround(d.length / kBushBlobPitch)));
  const double rx = 0.5 * d.length / blobs * 1.5;  // neighbours overlap
  Mesh m;
  m.name = "bush";
  for (uint32_t b = 0; b < blobs; ++b) {
    const double x = -0.5 * d.length + rx + (d.length - 2.0 * rx) * (static_cast<double>(b) / (blobs - 1));
    const double j = 1.0 - kBushBlobJitter * rng->uniform01();
    const double rz = 0.5 * d.height * j;
    add_ellipsoid(&m, {x, 0.0, ground + rz}, {rx * j, 0.5 * d.width * j, rz});
  }
  return finish(SceneObjectKind::kBush, std::move(m), frame_pose(at, base_z, yaw), d.base, t);
}

PlacedObject make_heap(const Terrain& t, const Eigen::Vector2d& at, double yaw, SeededRandom* rng) {
  const Drawn d = draw_size(t, at, yaw, kHeap, rng);
  // Centred at the lowest ground: the terrain hides its lower half.
  Mesh m;
  m.name = "heap";
  add_ellipsoid(&m, Eigen::Vector3d::Zero(),
                {0.5 * d.length, 0.5 * d.width, d.height + (d.ground.hi - d.ground.lo)});
  return finish(SceneObjectKind::kHeap, std::move(m), frame_pose(at, d.ground.lo, yaw), d.base, t);
}

const SizedClutter kSizedClutter[kSizedClutterKinds] = {{SceneObjectKind::kShed, make_shed},
                                                        {SceneObjectKind::kContainer, make_container},
                                                        {SceneObjectKind::kBush, make_bush},
                                                        {SceneObjectKind::kHeap, make_heap}};

}  // namespace spinhash::host
