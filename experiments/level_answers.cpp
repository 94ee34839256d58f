#include "level_answers.hpp"

#include "spinhash/answered.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::experiment {

LevelAnswers level_answers(const Result& r) {
  LevelAnswers a;
  if (!has_answer(r.status) || r.ranking_count == 0) return a;
  a.ranked = true;
  a.model = r.ranking[0].model;
  a.model_confident = r.confident;
  if (r.class_ranking_count > 0) a.vehicle_class = r.class_ranking[0].vehicle_class;
  a.class_confident = r.class_confident;
  a.group = static_cast<uint32_t>(vehicle_group_of(a.vehicle_class));
  a.group_confident = r.class_confident;
  a.vehicle_confident = r.confident || r.class_confident;
  a.level = a.model_confident     ? "model"
            : a.class_confident   ? "class"
            : a.group_confident   ? "group"
            : a.vehicle_confident ? "vehicle"
                                  : "none";
  return a;
}

}  // namespace spinhash::experiment
