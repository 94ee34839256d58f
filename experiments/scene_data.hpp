// The scene experiment's records: per tile, per vehicle, per false alarm.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scan/scene_simulator.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::experiment {

// One condition of the sweep: slope, spacing and noise of its tiles. The
// default condition belongs to every sweep.
struct SceneCondition {
  double slope_deg = 8.0;
  double spacing = 0.10;      // m on the ground, all views together
  double noise = 0.05;        // m along the ray
  std::string label() const;  // "slope 8, spacing 0.1, noise 0.05"
};

struct SceneTileRecord {
  uint32_t condition = 0, tile = 0;
  uint32_t points = 0;
  double ms = 0.0;  // SceneRecognizer::recognize wall time
  uint32_t vehicles = 0, found = 0, top1 = 0, confident_right = 0;
  uint32_t confident_wrong = 0;  // confident on a database vehicle, wrong model
  uint32_t false_alarms = 0;     // confident on a non-vehicle, an unknown vehicle or nothing
  uint32_t objects = 0;          // detected, of any kind
};

// A vehicle of the truth (known or unknown) and what was detected at it.
struct SceneVehicleRecord {
  uint32_t condition = 0, tile = 0;
  host::SceneObjectKind kind = host::SceneObjectKind::kVehicle;
  std::string model;
  uint32_t flags = 0;   // kSideBySide, kUnderTree
  uint32_t points = 0;  // simulated hits on it
  bool found = false;   // a vehicle-sized object within kMatchDistance
  double distance = 0.0;
  std::string answer;  // first-ranked model; empty when not found or not ranked
  bool confident = false;
  double score = 0.0;
  double score_second = 0.0;  // the runner-up's (0 without one)
  uint32_t features = 0;      // query features of the recognition (the margin's sqrt(n))
  double ground_gap = 0.0;    // SceneObject::ground_gap (NaN: none)
  // When not found: the nearest vehicle-sized object beyond reach (within
  // kNearestReach), to tell a miss from a detection off the footprint centre.
  double nearest_m = -1.0;  // -1: none
  std::string nearest_answer;
};

// A confident answer not on a database vehicle.
struct SceneFalseAlarm {
  uint32_t condition = 0, tile = 0;
  std::string on;  // nearest truth object's kind within kMatchDistance, or "nothing"
  std::string answer;
  double score = 0.0;
  double extent[3] = {0, 0, 0};
};

struct SceneRun {
  std::string out_dir, command, source, database, recognizer, tile_text;
  std::vector<SceneCondition> conditions;
  SceneCondition reference;  // the sweeps' centre
  std::vector<double> slopes, spacings, noises;
  uint32_t tiles = 0;  // per condition
  std::vector<SceneTileRecord> tile_records;
  std::vector<SceneVehicleRecord> vehicles;
  std::vector<SceneFalseAlarm> alarms;
  double seconds = 0.0;  // whole run, wall
};

// A detection matches a vehicle when its centre is this close (xy) to the
// vehicle's footprint centre.
constexpr double kMatchDistance = 1.5;  // m
constexpr double kNearestReach = 5.0;   // m: reported for the vehicles not found

// Scores one tile's answers against its truth and appends the records.
void score_tile(const host::SceneScan& scan, const SceneResult& result, const Database& db,
                uint32_t condition, uint32_t tile, double ms, SceneRun* run);

bool write_scene_report(const SceneRun& run, std::string* error);

}  // namespace spinhash::experiment
