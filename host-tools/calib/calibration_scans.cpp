#include "calib/calibration_scans.hpp"

#include <cmath>

#include "mesh/seeded_random.hpp"
#include "scan/ground_square.hpp"
#include "scan/scan_simulator.hpp"
#include "scan/scene_layout.hpp"
#include "scan/scene_terrain.hpp"
#include "spinhash/blob_format.hpp"
#include "util/angles.hpp"

namespace spinhash::calib {
namespace {

constexpr uint64_t kDrawStream = 0xCA11B;
constexpr uint64_t kClutterStream = 0xC1077E;
constexpr uint64_t kObjectStride = 1000003;  // prime: (object, index) pairs never share a seed

host::ScanOptions options_of(const ScanDraw& d) {
  host::ScanOptions o;
  o.views = d.views;
  o.elevation_deg = d.elevation_deg;
  o.noise_sigma = d.noise;
  o.point_spacing = d.spacing;
  o.seed = d.seed;
  o.occlusion = d.occlusion;
  o.random_pose = true;
  return o;
}

bool scan(const host::Mesh& mesh, const host::ScanOptions& o, host::ScanResult* out, std::string* error) {
  *out = host::simulate_scan(mesh, o);
  if (out->ok()) return true;
  *error = (mesh.name.empty() ? std::string("object") : mesh.name) + ": calibration scan: " + out->error;
  return false;
}

}  // namespace

ScanDraw draw_scan(uint64_t seed, uint32_t object, uint32_t index) {
  ScanDraw d;
  d.seed = host::mix_seed(seed, kObjectStride * object + index);
  host::SeededRandom rng(host::mix_seed(d.seed, kDrawStream));
  d.spacing = kMinSpacing * std::exp(rng.uniform(0.0, std::log(kMaxSpacing / kMinSpacing)));
  d.noise = rng.uniform(kMinNoise, kMaxNoise);
  d.occlusion = rng.uniform(0.0, kMaxOcclusion);
  d.views = kMinViews + rng.below(kMaxViews - kMinViews + 1u);
  d.elevation_deg = rng.uniform(kMinElevationDeg, kMaxElevationDeg);
  d.ground = rng.chance(kGroundShare);
  d.slope_deg = d.ground ? rng.uniform(0.0, kMaxSlopeDeg) : 0.0;
  return d;
}

bool scan_vehicle(const host::Mesh& mesh, const ScanDraw& d, std::vector<double>* xyz, std::string* error) {
  host::ScanOptions o = options_of(d);
  host::Mesh ground;
  if (d.ground) {
    ground = host::ground_square_around(mesh, kGroundMargin, mesh.bounding_box().lo.z());
    o.ground = &ground;
    o.ground_slope_deg = d.slope_deg;
  }
  host::ScanResult r;
  if (!scan(mesh, o, &r, error)) return false;
  *xyz = std::move(r.xyz);
  return true;
}

uint32_t clutter_kinds_scanned(uint32_t clutter) {
  return clutter == blob::kClutterVehicleSized ? kClutterKinds : static_cast<uint32_t>(ClutterKind::kShed);
}

const char* calibration_clutter_word(uint32_t clutter) {
  return clutter == blob::kClutterVehicleSized ? "vehicle-sized" : "tiles";
}

const char* calibration_clutter_kinds(uint32_t clutter) {
  return clutter == blob::kClutterVehicleSized
             ? "trees, walls, crates, buildings, sheds, freight containers, bushes, heaps"
             : "trees, walls, crates, buildings";
}

const char* clutter_name(ClutterKind kind) {
  constexpr const char* kNames[] = {"tree", "wall", "crate", "building", "shed", "container", "bush", "heap"};
  return kNames[static_cast<uint32_t>(kind) % kClutterKinds];
}

bool scan_clutter(ClutterKind kind, const ScanDraw& d, std::vector<double>* xyz, std::string* error) {
  const host::Terrain terrain(host::level_ground());
  host::SeededRandom rng(host::mix_seed(d.seed, kClutterStream));
  const Eigen::Vector2d at = Eigen::Vector2d::Zero();
  const double yaw = rng.uniform(0.0, 2.0 * host::kPi);
  host::PlacedObject p;
  switch (kind) {
    case ClutterKind::kTree: {
      const double a = rng.uniform(0.0, 2.0 * host::kPi), r = rng.uniform(0.0, 1.0);
      p = host::make_tree(terrain, at, at + r * Eigen::Vector2d(std::cos(a), std::sin(a)), 0.0, &rng);
      break;
    }
    case ClutterKind::kWall: p = host::make_wall(terrain, at, yaw, &rng); break;
    case ClutterKind::kCrate: p = host::make_crate(terrain, at, yaw, &rng); break;
    case ClutterKind::kBuilding: p = host::make_building(terrain, at, yaw, &rng); break;
    case ClutterKind::kShed: p = host::make_shed(terrain, at, yaw, &rng); break;
    case ClutterKind::kContainer: p = host::make_container(terrain, at, yaw, &rng); break;
    case ClutterKind::kBush: p = host::make_bush(terrain, at, yaw, &rng); break;
    case ClutterKind::kHeap: p = host::make_heap(terrain, at, yaw, &rng); break;
  }
  p.mesh.name = clutter_name(kind);
  const host::Mesh ground = host::ground_square_around(p.mesh, kGroundMargin, 0.0);  // the flat terrain
  host::ScanOptions o = options_of(d);
  o.ground = &ground;
  o.ground_slope_deg = d.slope_deg;
  host::ScanResult r;
  if (!scan(p.mesh, o, &r, error)) return false;
  xyz->clear();
  for (size_t i = 0; i < r.size(); ++i) {
    if (!d.ground && r.on_object[i] == 0u) continue;
    xyz->insert(xyz->end(), r.xyz.begin() + static_cast<std::ptrdiff_t>(3 * i),
                r.xyz.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
  }
  return true;
}

}  // namespace spinhash::calib
