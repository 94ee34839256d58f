// Which Warzone 2100 PIE files make a vehicle or a structure. The body ->
// propulsion pairs are those of stats/body.json ("propulsionExtraModels")
// in warzone2100-data 4.3.3: the propulsion model is drawn at the body's
// origin, so a vehicle is the two meshes merged. VTOL and cyborg parts are
// left out (aircraft and people, not ground vehicles).
#pragma once
#include <string>
#include <vector>

namespace spinhash::experiment {

struct WarzoneVehicle {
  std::string name;                // e.g. "wz-drlbod01-tracks"
  std::vector<std::string> parts;  // paths under the base.wz root
  std::string klass;               // vehicle class (include/spinhash/vehicle_classes.h)
  std::string group;               // its group where its class has none ("": its class's)
};

// Droid bodies x ground propulsion (wheels, half-tracks, tracks, hover),
// plus the one-piece "Babas" vehicles (jeep, buggy, trike, bus, fire truck).
// Classes: the armoured droid bodies are wheeled APCs on wheels and tracked
// vehicles on tracks or half-tracks (their rear runs on tracks); on hover
// they are "other" (a hovercraft is no class of the list). The jeeps are
// SUVs, the buggies and the trike "other", the school bus a bus and the
// fire engine a truck.
std::vector<WarzoneVehicle> warzone_vehicles();

// Directories of the structures and of the map features (trees, rocks,
// wrecks, ruins) under the base.wz root, and whether a file there is a
// texture-only variant of another (same geometry: *_col, *_nex).
constexpr const char* kWarzoneStructureDir = "structs";
constexpr const char* kWarzoneFeatureDir = "features";
bool is_texture_variant(const std::string& stem);

}  // namespace spinhash::experiment
