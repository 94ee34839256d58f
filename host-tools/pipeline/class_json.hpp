// The class level of an answer as JSON members: "class", "class_confident"
// and "class_ranking", written by `recognize`'s and `scene`'s lines (and so
// the survey's outputs) from this one list of keys
// (tests/host/test_field_mirrors.cpp checks it against docs/cli.md).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/object_json.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash::pipeline {

namespace class_keys {
constexpr const char* kClass = "class";                     // the first class's name, null without a ranking
constexpr const char* kClassConfident = "class_confident";  // Result::class_confident
constexpr const char* kClassRanking = "class_ranking";      // [{class, score, model}], best first
constexpr const char* kScore = "score";                     // the class's best model's score
constexpr const char* kModel = "model";                     // that model
constexpr const char* kAll[] = {kClass, kClassConfident, kClassRanking, kScore, kModel};
}  // namespace class_keys

std::vector<JsonMember> class_members(const Database& db, const RankedClass* ranking, uint32_t count,
                                      bool confident);
// The same members as "key":value,... (no braces), for lines written by hand.
std::string class_json(const Database& db, const RankedClass* ranking, uint32_t count, bool confident);

}  // namespace spinhash::pipeline
