#include "world_set.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "csv_reader.hpp"
#include "mesh/mesh_loader.hpp"
#include "mesh/seeded_random.hpp"
#include "model_set.hpp"
#include "scan/scene_layout.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::experiment {
namespace {

namespace fs = std::filesystem;

constexpr uint64_t kVehicleSizedStream = 0x5E1C;  // its own draws: the scene clutter's stay as they were

// Mesh files under `root`, any depth, by stem.
std::map<std::string, std::string> mesh_files_under(const fs::path& root) {
  std::map<std::string, std::string> out;
  std::vector<fs::path> dirs{root};
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory()) dirs.push_back(it->path());
  for (const fs::path& d : dirs) {
    std::string ignored;
    for (const std::string& f : host::list_mesh_files(d.string(), &ignored))
      out.emplace(fs::path(f).stem().string(), f);
  }
  return out;
}

std::string world_of_source(const std::string& source) { return source.substr(0, source.find('-')); }

void add_world(const std::string& world, WorldSet* set) {
  if (set->world_index(world) == set->worlds.size()) set->worlds.push_back(world);
}

}  // namespace

std::vector<uint32_t> WorldSet::vehicles_of(uint32_t w) const {
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < vehicles.size(); ++i)
    if (vehicles[i].world == worlds[w]) out.push_back(i);
  return out;
}

uint32_t WorldSet::world_index(const std::string& world) const {
  uint32_t i = 0;
  while (i < worlds.size() && worlds[i] != world) ++i;
  return i;
}

void add_fleet_world(uint32_t count, uint64_t fleet_seed, WorldSet* set) {
  if (count == 0) return;
  add_world("fleet", set);
  for (pipeline::ModelMesh& m : generated_models(count, fleet_seed)) {
    set->vehicles.push_back(WorldVehicle{"fleet", std::move(m)});
  }
}

bool add_catalog(const std::string& path, const std::vector<std::string>& clutter_sources, WorldSet* set,
                 std::string* error) {
  const fs::path csv = fs::is_directory(path) ? fs::path(path) / "catalog.csv" : fs::path(path);
  CsvReader catalog;
  if (!catalog.read(csv.string(), error)) return false;
  const int name = catalog.column("name"), klass = catalog.column("class"), source = catalog.column("source");
  const int group_column = catalog.column("group");  // optional: the class's group where absent or empty
  if (name < 0 || klass < 0 || source < 0) {
    *error = csv.string() + ": needs the columns name, class and source";
    return false;
  }
  const std::map<std::string, std::string> files = mesh_files_under(csv.parent_path());
  for (size_t r = 0; r < catalog.rows(); ++r) {
    const std::string& n = catalog.cell(r, name);
    const std::string& k = catalog.cell(r, klass);
    const std::string& s = catalog.cell(r, source);
    const bool clutter =
        k.empty() && std::find(clutter_sources.begin(), clutter_sources.end(), s) != clutter_sources.end();
    if (k.empty() && !clutter) continue;
    VehicleClass c = VehicleClass::kUnclassified;
    if (!clutter && (!parse_vehicle_class(k.c_str(), &c) || c == VehicleClass::kUnclassified)) {
      *error = csv.string() + ": " + n + ": '" + k + "' is not a vehicle class";
      return false;
    }
    const VehicleGroup class_group = vehicle_group_of(c);
    VehicleGroup group = class_group;
    const std::string g = group_column < 0 || clutter ? std::string() : catalog.cell(r, group_column);
    if (!g.empty() && !parse_vehicle_group(g.c_str(), &group)) {
      *error = csv.string() + ": " + n + ": '" + g + "' is not a vehicle group";
      return false;
    }
    if (class_group != VehicleGroup::kNone && group != class_group) {
      *error = csv.string() + ": " + n + ": group '" + g + "', but class '" + k + "' is in group '" +
               vehicle_group_name(class_group) +
               "' (only a class in no group takes a group of its vehicle's)";
      return false;
    }
    // Only a class in no group carries a group of its own; 0: its class's.
    const VehicleGroup own_group = class_group == VehicleGroup::kNone ? group : VehicleGroup::kNone;
    const auto file = files.find(n);
    host::Mesh mesh;
    if (file == files.end()) {
      *error = csv.string() + ": no mesh file named " + n + " under " + csv.parent_path().string();
      return false;
    }
    if (!host::load_mesh(file->second, &mesh, error)) return false;
    if (clutter) {
      const double ground = mesh.bounding_box().lo.z();
      set->clutter.push_back(ClutterObject{s, s, n, std::move(mesh), ground});
      continue;
    }
    add_world(world_of_source(s), set);
    set->vehicles.push_back(
        WorldVehicle{world_of_source(s), pipeline::ModelMesh{n, std::move(mesh), c, own_group}});
  }
  return true;
}

void add_scene_clutter(uint32_t per_kind, uint64_t seed, WorldSet* set) {
  const host::Terrain terrain(host::level_ground());
  const Eigen::Vector2d at = Eigen::Vector2d::Zero();
  host::SeededRandom rng(host::mix_seed(seed, 0));
  const char* kinds[] = {"tree", "wall", "crate", "building"};
  for (uint32_t i = 0; i < per_kind; ++i)
    for (const char* kind : kinds) {
      host::PlacedObject p;
      const std::string k = kind;
      if (k == "tree") {
        const double a = rng.uniform(0.0, 6.283185307179586), r = rng.uniform(0.0, 1.0);
        p = host::make_tree(terrain, at, at + r * Eigen::Vector2d(std::cos(a), std::sin(a)), 0.0, &rng);
      } else if (k == "wall") {
        p = host::make_wall(terrain, at, 0.0, &rng);
      } else if (k == "crate") {
        p = host::make_crate(terrain, at, 0.0, &rng);
      } else {
        p = host::make_building(terrain, at, 0.0, &rng);
      }
      set->clutter.push_back(ClutterObject{"scene", k, k + "-" + std::to_string(i), std::move(p.mesh),
                                           terrain.height(0.0, 0.0)});
    }
}

void add_vehicle_sized_clutter(uint32_t per_kind, uint64_t seed, WorldSet* set) {
  const host::Terrain terrain(host::level_ground());
  host::SeededRandom rng(host::mix_seed(seed, kVehicleSizedStream));
  for (uint32_t i = 0; i < per_kind; ++i)
    for (const host::SizedClutter& sized : host::kSizedClutter) {
      host::PlacedObject p = sized.make(terrain, Eigen::Vector2d::Zero(), 0.0, &rng);
      const std::string kind = host::scene_object_kind_name(sized.kind);
      set->clutter.push_back(ClutterObject{"vehicle-sized", kind, kind + "-" + std::to_string(i),
                                           std::move(p.mesh), terrain.height(0.0, 0.0)});
    }
}

bool check_world_set(const WorldSet& set, std::string* error) {
  uint32_t with_vehicles = 0;
  for (uint32_t w = 0; w < set.worlds.size(); ++w) with_vehicles += set.vehicles_of(w).empty() ? 0u : 1u;
  if (with_vehicles < 2) {
    *error = "leaving one world out needs at least two worlds with vehicles (" +
             std::to_string(with_vehicles) + " given)";
    return false;
  }
  std::set<std::string> names;
  for (const WorldVehicle& v : set.vehicles)
    if (!names.insert(v.model.name).second) {
      *error = "two vehicles are named " + v.model.name + " (a database's model names must differ)";
      return false;
    }
  return true;
}

}  // namespace spinhash::experiment
