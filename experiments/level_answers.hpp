// What a recognition answers at each level of the hierarchy (vehicle,
// group, class, model) and whether it is confident there: the one place
// the leave-one-world-out experiment reads a Result's flags.
//
// The recognizer flags the model (`confident`) and the class
// (`class_confident`); a group is a function of the class
// (vehicle_group_of). Here the group is the first class's, confident when
// the class is (a confident class names its group), and the vehicle level
// is confident when any flag is raised.
#pragma once
#include <cstdint>

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
  // The most specific confident level: "model", "class", "group", "vehicle", or "none".
  const char* level = "none";
};

LevelAnswers level_answers(const Result& r);

}  // namespace spinhash::experiment
