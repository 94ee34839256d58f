// The worlds of the leave-one-world-out experiment: independent sources of
// vehicle meshes (the procedural fleet, each game's or library's vehicles),
// each vehicle with its class, and the non-vehicles scanned beside them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "pipeline/model_sources.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::experiment {

struct WorldVehicle {
  std::string world;
  // Name, mesh (x forward, z up, resting at z = 0), class, and the catalog's
  // group where the class spans the groups (other): built into the model's
  // record, as `spinhash build --classes` does.
  pipeline::ModelMesh model;
  // The vehicle's own group, what a group answer is judged against.
  VehicleGroup group() const {
    return vehicle_group_of(static_cast<uint32_t>(model.vehicle_class),
                            static_cast<uint32_t>(model.vehicle_group));
  }
};

// Something that is no vehicle, standing on level ground at height ground_z
// of its own frame (anything below is a foundation the ground hides).
struct ClutterObject {
  std::string source;  // "scene" (the scene simulator's) or its catalog source (warzone-structure)
  std::string kind;    // tree, wall, crate, building; a catalog's: its source
  std::string name;
  host::Mesh mesh;
  double ground_z = 0.0;
};

struct WorldSet {
  std::vector<std::string> worlds;  // in the order they were added
  std::vector<WorldVehicle> vehicles;
  std::vector<ClutterObject> clutter;
  // Vehicles of world `w` (an index into worlds).
  std::vector<uint32_t> vehicles_of(uint32_t w) const;
  uint32_t world_index(const std::string& world) const;  // worlds.size() when absent
};

// The procedural fleet (`spinhash generate`): `count` members, world "fleet".
void add_fleet_world(uint32_t count, uint64_t fleet_seed, WorldSet* set);

// The meshes a catalog.csv lists (scripts/prepare-*.sh: columns name,
// class, source, and group where a vehicle's class has none: a class in a
// group keeps it), found by file stem anywhere under the catalog's folder.
// A row with a class is a vehicle of the world its source's first word
// names ("torcs", "sweethome3d-Scopia": "sweethome3d", "warzone-vehicle":
// "warzone"); a row without a class is clutter of kind `source` when
// clutter_sources lists that source, else left out (map features: wrecks
// and ruins that look like vehicles). `path` is the catalog or its folder.
bool add_catalog(const std::string& path, const std::vector<std::string>& clutter_sources, WorldSet* set,
                 std::string* error);

// The scene simulator's clutter (host-tools/scan/scene_clutter.cpp):
// `per_kind` trees, walls, crates and buildings on level ground.
void add_scene_clutter(uint32_t per_kind, uint64_t seed, WorldSet* set);

// Non-vehicles of a vehicle's size and bulk (the same file): `per_kind`
// sheds, freight containers, bushes and heaps on level ground, source
// "vehicle-sized". No tile holds them and no calibration scans them.
void add_vehicle_sized_clutter(uint32_t per_kind, uint64_t seed, WorldSet* set);

// false with *error when fewer than two worlds hold vehicles, or two
// vehicles share a name (the database's model names).
bool check_world_set(const WorldSet& set, std::string* error);

}  // namespace spinhash::experiment
