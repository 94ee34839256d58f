#include "pipeline/level_json.hpp"

#include "pipeline/json_line.hpp"
#include "pipeline/recognition_session.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::pipeline {

LevelView level_view(const Result& r) {
  LevelView v;
  if (r.status != Status::kOk) return v;
  v.groups = r.group_ranking;
  v.group_count = r.group_ranking != nullptr ? r.group_ranking_count : 0u;
  v.levels = r.levels;
  v.level = r.level;
  return v;
}

LevelView level_view(const SceneObject& o) {
  LevelView v;
  v.groups = o.groups;
  v.group_count = o.group_count;
  v.levels = o.levels;
  v.level = o.level;
  return v;
}

std::vector<JsonMember> level_members(const Database& db, const LevelView& v) {
  namespace k = level_keys;
  std::string ranking;
  for (uint32_t i = 0; i < v.group_count; ++i)
    ranking += std::string(i ? "," : "") + "{" +
               json_member(k::kGroup, json_string(vehicle_group_name(v.groups[i].group))) + "," +
               json_member(k::kScore, json_number(static_cast<double>(v.groups[i].score), 7)) + "," +
               json_member(k::kModel, json_string(model_name(db, v.groups[i].model))) + "}";
  std::string levels;
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
    const LevelAnswer a = v.levels != nullptr ? v.levels[l] : LevelAnswer{};
    levels += std::string(l ? "," : "") + json_string(answer_level_name(l + 1u)) + ":{" +
              json_member(k::kConfident, a.confident ? "true" : "false") + "," +
              json_member(k::kEvidence, json_number(static_cast<double>(a.evidence), 6)) + "}";
  }
  return {
      {k::kGroup,
       v.group_count > 0 ? json_string(vehicle_group_name(v.groups[0].group)) : std::string("null")},
      {k::kGroupRanking, "[" + ranking + "]"},
      {k::kLevels, "{" + levels + "}"},
      {k::kLevel, json_string(answer_level_name(static_cast<uint32_t>(v.level)))},
  };
}

std::string level_json(const Database& db, const LevelView& v) {
  std::string s;
  for (const JsonMember& m : level_members(db, v))
    s += (s.empty() ? "" : ",") + json_member(m.key.c_str(), m.value);
  return s;
}

}  // namespace spinhash::pipeline
