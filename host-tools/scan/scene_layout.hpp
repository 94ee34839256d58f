// The tile simulator's layout: footprints, vehicles resting on the terrain,
// clutter, and the seeded placement that keeps them apart.
#pragma once

#include "mesh/mesh.hpp"
#include "mesh/seeded_random.hpp"
#include "scan/scene_simulator.hpp"
#include "scan/scene_terrain.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spinhash::host {

// Oriented rectangle in the xy plane.
struct Footprint {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  Eigen::Vector2d half = Eigen::Vector2d::Zero();  // along the heading, across it
  double heading = 0.0;                            // radians from +x
  Eigen::Vector2d axis() const;                    // unit, along the heading
  Eigen::Vector2d lateral() const;                 // unit, 90 degrees left of it
};

// True when the rectangles, each grown by clearance / 2, overlap (separating axes).
bool footprints_overlap(const Footprint& a, const Footprint& b, double clearance);
// Smallest rectangle of the given heading holding every vertex of the mesh (xy).
Footprint footprint_of(const Mesh& mesh, double heading);
// Every corner of the footprint at least `margin` inside the tile.
bool inside_tile(const Footprint& f, double size, double margin);

// One object of the scene, in the tile-local frame.
struct PlacedObject {
  SceneTruth truth;  // pose and center local; points not yet counted
  Mesh mesh;         // posed
  Footprint base;    // what stands on the ground
  bool has_crown = false;
  Footprint crown;   // a tree's crown (overhangs vehicles, nothing else)
  double top = 0.0;  // highest z
  double crown_bottom = 0.0;
};

// Model -> local pose of `model` resting on the terrain at xy `at` with
// heading `yaw`: its up axis along the normal of the plane fitted to the
// terrain under its footprint, lowered until its lowest vertex touches.
Eigen::Matrix4d rest_on_terrain(const Mesh& model, const Terrain& terrain, const Eigen::Vector2d& at,
                                double yaw);
PlacedObject place_vehicle(const Mesh& model, SceneObjectKind kind, const Terrain& terrain,
                           const Eigen::Vector2d& at, double yaw);

// Clutter (scene_clutter.cpp), drawn from rng at xy `at`, heading `yaw`.
PlacedObject make_building(const Terrain& terrain, const Eigen::Vector2d& at, double yaw, SeededRandom* rng);
PlacedObject make_wall(const Terrain& terrain, const Eigen::Vector2d& at, double yaw, SeededRandom* rng);
PlacedObject make_crate(const Terrain& terrain, const Eigen::Vector2d& at, double yaw, SeededRandom* rng);
// Vehicle-sized non-vehicles: a shed or garage, an ISO freight container, a
// bush or hedge, a heap.
PlacedObject make_shed(const Terrain& terrain, const Eigen::Vector2d& at, double yaw, SeededRandom* rng);
PlacedObject make_container(const Terrain& terrain, const Eigen::Vector2d& at, double yaw, SeededRandom* rng);
PlacedObject make_bush(const Terrain& terrain, const Eigen::Vector2d& at, double yaw, SeededRandom* rng);
PlacedObject make_heap(const Terrain& terrain, const Eigen::Vector2d& at, double yaw, SeededRandom* rng);
// Those four with their makers, in the order tiles place them (SceneOptions
// sheds, containers, bushes, heaps) and the worlds experiment scans them;
// each is named by scene_object_kind_name(kind).
using ClutterMaker = PlacedObject (*)(const Terrain&, const Eigen::Vector2d&, double, SeededRandom*);
struct SizedClutter {
  SceneObjectKind kind;
  ClutterMaker make;
};
constexpr uint32_t kSizedClutterKinds = 4;
extern const SizedClutter kSizedClutter[kSizedClutterKinds];
// Trunk at `at`, crown centred at crown_at, its underside at least min_crown_bottom (z, local).
PlacedObject make_tree(const Terrain& terrain, const Eigen::Vector2d& at, const Eigen::Vector2d& crown_at,
                       double min_crown_bottom, SeededRandom* rng);

// Places everything options ask for; false with *error when some object
// finds no free place in kMaxPlacementAttempts draws.
bool lay_out_scene(const std::vector<Mesh>& vehicles, const std::vector<Mesh>& unknown, const SceneOptions& o,
                   const Terrain& terrain, std::vector<PlacedObject>* out, std::string* error);

}  // namespace spinhash::host
