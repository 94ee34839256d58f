// experiment worlds: per_scan.csv, one row per scan and database.
#include <limits>

#include "csv_table.hpp"
#include "spinhash/vehicle_class.hpp"
#include "worlds_data.hpp"

namespace spinhash::experiment {
namespace {

std::string flag(bool b) { return b ? "1" : "0"; }

// A level's evidence; empty where a prerequisite failed (no threshold reaches it).
std::string evidence(const LevelAnswers& a, AnswerLevel l) {
  const float e = a.evidence[level_index(l)];
  if (!a.ranked || !(e > -std::numeric_limits<float>::infinity())) return "";
  if (!(e < std::numeric_limits<float>::infinity())) return "inf";  // unopposed
  return num(e, 5);
}

}  // namespace

bool write_worlds_csv(const WorldsRun& run, std::string* error) {
  CsvTable t({"world",
              "object",
              "kind",
              "true_class",
              "true_group",
              "condition",
              "scan",
              "seed",
              "spacing_m",
              "density",
              "noise_m",
              "occlusion",
              "ground",
              "slope_deg",
              "points",
              "object_points",
              "database",
              "status",
              "first_model",
              "first_world",
              "model_right",
              "model_confident",
              "first_class",
              "class_right",
              "class_confident",
              "first_group",
              "group_right",
              "group_confident",
              "vehicle_confident",
              "vehicle_evidence",
              "group_evidence",
              "class_evidence",
              "model_evidence",
              "level",
              "scan_density",
              "ms"});
  const WorldSet& set = *run.set;
  for (const WorldsRecord& r : run.records) {
    const WorldsJudgement j = judge(run, r);
    const bool ranked = r.answer.ranked;
    std::string world, object, kind, true_class, true_group;
    if (r.clutter) {
      const ClutterObject& c = set.clutter[r.object];
      world = c.source;
      object = c.name;
      kind = c.kind;
    } else {
      const WorldVehicle& v = set.vehicles[r.object];
      world = v.world;
      object = v.model.name;
      kind = "vehicle";
      true_class = vehicle_class_name(j.true_class);
      true_group = vehicle_group_name(j.true_group);
    }
    const bool first_known = ranked && r.first >= 0;
    t.add({world,
           object,
           kind,
           true_class,
           true_group,
           run.conditions[r.condition].name,
           std::to_string(r.scan),
           std::to_string(r.draw.seed),
           num(r.draw.spacing, 4),
           num(r.draw.density, 4),
           num(r.draw.noise, 3),
           num(r.draw.occlusion, 3),
           flag(r.draw.ground),
           num(r.draw.slope_deg, 3),
           std::to_string(r.points),
           std::to_string(r.object_points),
           worlds_database_name(r.database),
           status_name(r.status),
           first_known ? set.vehicles[static_cast<size_t>(r.first)].model.name : "",
           first_known ? set.vehicles[static_cast<size_t>(r.first)].world : "",
           flag(j.model_right),
           flag(r.answer.model_confident),
           ranked ? vehicle_class_name(r.answer.vehicle_class) : "",
           flag(j.class_right),
           flag(r.answer.class_confident),
           ranked ? vehicle_group_name(r.answer.group) : "",
           flag(j.group_right),
           flag(r.answer.group_confident),
           flag(r.answer.vehicle_confident),
           evidence(r.answer, AnswerLevel::kVehicle),
           evidence(r.answer, AnswerLevel::kGroup),
           evidence(r.answer, AnswerLevel::kClass),
           evidence(r.answer, AnswerLevel::kModel),
           r.answer.level,
           num(r.scan_density, 4),
           num(r.ms, 4)});
  }
  return t.write(run.out_dir + "/per_scan.csv", error);
}

}  // namespace spinhash::experiment
