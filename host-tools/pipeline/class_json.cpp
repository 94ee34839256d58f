#include "pipeline/class_json.hpp"

#include "pipeline/json_line.hpp"
#include "pipeline/recognition_session.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash::pipeline {

std::vector<JsonMember> class_members(const Database& db, const RankedClass* ranking, uint32_t count,
                                      bool confident) {
  namespace k = class_keys;
  std::string list;
  for (uint32_t i = 0; i < count; ++i) {
    list += std::string(i ? "," : "") + "{" +
            json_member(k::kClass, json_string(vehicle_class_name(ranking[i].vehicle_class))) + "," +
            json_member(k::kScore, json_number(static_cast<double>(ranking[i].score), 7)) + "," +
            json_member(k::kModel, json_string(model_name(db, ranking[i].model))) + "}";
  }
  return {
      {k::kClass,
       count > 0 ? json_string(vehicle_class_name(ranking[0].vehicle_class)) : std::string("null")},
      {k::kClassConfident, confident ? "true" : "false"},
      {k::kClassRanking, "[" + list + "]"},
  };
}

std::string class_json(const Database& db, const RankedClass* ranking, uint32_t count, bool confident) {
  std::string s;
  for (const JsonMember& m : class_members(db, ranking, count, confident))
    s += (s.empty() ? "" : ",") + json_member(m.key.c_str(), m.value);
  return s;
}

}  // namespace spinhash::pipeline
