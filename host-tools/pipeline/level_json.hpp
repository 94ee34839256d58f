// The answer levels as JSON members: "group", "group_ranking", "levels" and
// "level", written by `recognize`'s and `scene`'s lines (and so the
// survey's JSON lines, GeoJSON properties and GeoPackage columns) from this
// one list of keys (tests/host/test_field_mirrors.cpp checks it against
// docs/cli.md and the output).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/object_json.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash::pipeline {

namespace level_keys {
constexpr const char* kGroup = "group";                 // the first group's name, null without a ranking
constexpr const char* kGroupRanking = "group_ranking";  // [{group, score, model}], best first
constexpr const char* kScore = "score";                 // the group's best model's score
constexpr const char* kModel = "model";                 // that model
// {"vehicle":{confident, evidence},"group":..,"class":..,"model":..}: per
// calibrated level (answer_levels.h) its flag and evidence
constexpr const char* kLevels = "levels";
constexpr const char* kConfident = "confident";
constexpr const char* kEvidence = "evidence";  // null when not finite (failed prerequisite, or unopposed)
// the most specific confident level whose coarser levels are confident and
// consistent: "vehicle", "group", "class", "model", or "none"
constexpr const char* kLevel = "level";
constexpr const char* kAll[] = {kGroup,  kGroupRanking, kScore,    kModel,
                                kLevels, kConfident,    kEvidence, kLevel};
}  // namespace level_keys

// An answer's levels (a Result's or a SceneObject's).
struct LevelView {
  const RankedGroup* groups = nullptr;
  uint32_t group_count = 0;
  const LevelAnswer* levels = nullptr;  // kCalibratedLevels of them; null: none confident
  AnswerLevel level = AnswerLevel::kNone;
};
LevelView level_view(const Result& r);  // empty unless r.status is kOk
LevelView level_view(const SceneObject& o);

std::vector<JsonMember> level_members(const Database& db, const LevelView& v);
// The same members as "key":value,... (no braces), for lines written by hand.
std::string level_json(const Database& db, const LevelView& v);

}  // namespace spinhash::pipeline
