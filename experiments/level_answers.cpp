#include "level_answers.hpp"

#include "spinhash/answered.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::experiment {

LevelAnswers level_answers(const Result& r) {
  LevelAnswers a;
  if (!has_answer(r.status) || r.ranking_count == 0) return a;
  a.ranked = true;
  a.model = r.ranking[0].model;
  if (r.class_ranking_count > 0) a.vehicle_class = r.class_ranking[0].vehicle_class;
  a.group = r.group_ranking_count > 0 ? r.group_ranking[0].group
                                      : static_cast<uint32_t>(vehicle_group_of(a.vehicle_class));
  const auto flag = [&r](AnswerLevel l) { return r.levels[level_index(l)].confident; };
  a.model_confident = r.confident;
  a.class_confident = r.class_confident;
  a.group_confident = flag(AnswerLevel::kGroup);
  a.vehicle_confident = flag(AnswerLevel::kVehicle);
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) a.evidence[l] = r.levels[l].evidence;
  a.answer_level = r.level;
  a.level = answer_level_name(static_cast<uint32_t>(r.level));
  return a;
}

}  // namespace spinhash::experiment
