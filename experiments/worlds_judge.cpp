#include "spinhash/vehicle_class.hpp"
#include "worlds_data.hpp"

namespace spinhash::experiment {

const char* worlds_database_name(WorldsDatabase d) {
  return d == WorldsDatabase::kLeftOut ? "left-out" : "all";
}

WorldsJudgement judge(const WorldsRun& run, const WorldsRecord& r) {
  WorldsJudgement j;
  if (r.clutter) return j;
  const WorldVehicle& v = run.set->vehicles[r.object];
  j.true_class = static_cast<uint32_t>(v.model.vehicle_class);
  // The vehicle's own group: a buggy is light, though its class (other) is in none.
  j.true_group = static_cast<uint32_t>(v.group());
  if (!r.answer.ranked) return j;
  j.model_right = r.first == static_cast<int32_t>(r.object);
  j.class_right = r.answer.vehicle_class == j.true_class;
  j.group_right = r.answer.group == j.true_group;
  return j;
}

}  // namespace spinhash::experiment
