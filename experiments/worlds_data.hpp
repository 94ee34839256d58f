// What `experiment worlds` measured: one record per scan and database.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "level_answers.hpp"
#include "world_conditions.hpp"
#include "world_set.hpp"

namespace spinhash::experiment {

// Which database a scan was recognised with.
enum class WorldsDatabase : uint8_t {
  kLeftOut,  // every world's vehicles but the scanned vehicle's world
  kAll,      // every world's vehicles
};
const char* worlds_database_name(WorldsDatabase d);  // "left-out", "all"

struct WorldsRecord {
  bool clutter = false;
  uint32_t object = 0;  // index into WorldSet::vehicles, or WorldSet::clutter
  uint32_t condition = 0;
  uint32_t scan = 0;
  ScanDraw draw;
  uint32_t points = 0, object_points = 0;
  WorldsDatabase database = WorldsDatabase::kAll;
  Status status = Status::kNotOpen;
  int32_t first = -1;  // the first model as an index into WorldSet::vehicles; -1 without a ranking
  LevelAnswers answer;
  float scan_density = 0.0f;  // RecognitionStats::scan_density
  double ms = 0.0;
};

// One database built for the run.
struct WorldsDatabaseInfo {
  std::string name;  // "all", "without-<world>"
  std::string path;
  uint32_t models = 0, features = 0;
  uint64_t bytes = 0;
  double seconds = 0.0;
};

struct WorldsRun {
  std::string out_dir;
  std::string command;
  std::string version;
  std::string recognizer;  // config_text
  const WorldSet* set = nullptr;
  std::vector<WorldsCondition> conditions;
  std::vector<uint32_t> scans_per_vehicle;  // per world (index into set->worlds)
  uint32_t clutter_scans = 0;               // per piece of clutter, sparse condition only
  std::vector<WorldsDatabaseInfo> databases;
  std::vector<WorldsRecord> records;
  double seconds = 0.0;  // the whole run
};

// Which levels of a record's answer name the truth. Clutter: nothing is
// right. A vehicle of the class "other" is in no group: a group answer
// names its group only when it is none.
struct WorldsJudgement {
  uint32_t true_class = 0, true_group = 0;  // VehicleClass, VehicleGroup ids (0 for clutter)
  bool model_right = false;                 // the first model is the scanned vehicle
  bool class_right = false, group_right = false;
};
WorldsJudgement judge(const WorldsRun& run, const WorldsRecord& r);

// per_scan.csv (worlds_csv.cpp) and summary.md into run.out_dir.
bool write_worlds_csv(const WorldsRun& run, std::string* error);
bool write_worlds_report(const WorldsRun& run, std::string* error);

}  // namespace spinhash::experiment
