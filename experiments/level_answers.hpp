// What a recognition answers at each level of the hierarchy (vehicle,
// group, class, model), each level's calibrated flag and evidence as the
// recognizer reports them (Result::levels), and the answer's level
// (Result::level, the most specific confident level of a consistent
// chain): the one place the leave-one-world-out experiment reads a
// Result's flags.
#pragma once
#include <cstdint>

#include "spinhash/calibration.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash::experiment {

struct LevelAnswers {
  bool ranked = false;  // the ranking holds a model (the rest is valid only then)
  uint32_t model = 0;   // the first model (database index)
  bool model_confident = false;
  uint32_t vehicle_class = 0;  // VehicleClass id of the first class
  bool class_confident = false;
  uint32_t group = 0;  // VehicleGroup id of the first group
  bool group_confident = false;
  bool vehicle_confident = false;
  float evidence[kCalibratedLevels] = {};  // vehicle .. model (Result::levels)
  AnswerLevel answer_level = AnswerLevel::kNone;
  // The most specific confident level: "model", "class", "group", "vehicle", or "none".
  const char* level = "none";

  // A flag raised at any level.
  bool any_confident() const {
    return vehicle_confident || group_confident || class_confident || model_confident;
  }
  // The answer stands at `l` or a more specific level.
  bool at_least(AnswerLevel l) const { return answer_level >= l; }
};

LevelAnswers level_answers(const Result& r);

}  // namespace spinhash::experiment
