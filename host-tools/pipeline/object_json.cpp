#include "pipeline/object_json.hpp"

#include <cmath>

#include "pipeline/class_json.hpp"
#include "pipeline/json_line.hpp"
#include "pipeline/level_json.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/status_word.hpp"
#include "pipeline/version.hpp"

namespace spinhash::pipeline {
namespace {

std::string triple_json(const double v[3], int digits) {
  return "[" + json_number(v[0], digits) + "," + json_number(v[1], digits) + "," + json_number(v[2], digits) +
         "]";
}

std::string ranking_json(const Database& db, const SceneObject& o) {
  std::string s = "[";
  for (uint32_t j = 0; j < o.ranking_count; ++j)
    s += std::string(j ? "," : "") + "{\"model\":" + json_string(model_name(db, o.ranking[j].model)) +
         ",\"score\":" + json_number(o.ranking[j].score) + "}";
  return s + "]";
}

}  // namespace

std::string pose_json(const Pose& p) {
  std::string s = "[";
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) s += json_number(static_cast<double>(p.rotation[3 * r + c])) + ",";
    s += json_number(p.translation[r], 15) + ",";  // georeferenced: keep millimetres at 10^7 m
  }
  return s + "0,0,0,1]";
}

std::vector<JsonMember> object_members(const std::string& tile, uint32_t k, const Database& db,
                                       const SceneObject& o) {
  const bool ranked = o.ranking_count > 0;
  const double extent[3] = {o.extent[0], o.extent[1], o.extent[2]};
  std::vector<JsonMember> members = {
      {"tile", json_string(tile)},
      {"object", std::to_string(k)},
      {"kind", json_string(object_kind_name(o.kind))},
      {"status", std::string("\"") + status_word(o.status) + "\""},
      {"model", ranked ? json_string(model_name(db, o.ranking[0].model)) : "null"},
      {"confident", o.confident ? "true" : "false"},
      {"group_size", std::to_string(o.group_size)},
  };
  for (JsonMember& m : class_members(db, o.classes, o.class_count, o.class_confident)) members.push_back(m);
  for (JsonMember& m : level_members(db, level_view(o))) members.push_back(m);
  const std::vector<JsonMember> rest = {
      {"score", ranked ? json_number(o.ranking[0].score) : "null"},
      {"ranking", ranking_json(db, o)},
      {"pose", ranked && o.ranking[0].has_pose ? pose_json(o.ranking[0].pose) : std::string("null")},
      {"ground_gap", std::isfinite(o.ground_gap) ? json_number(o.ground_gap, 4) : std::string("null")},
      {"points", std::to_string(o.points)},
      {"center", triple_json(o.center, 15)},
      {"extent", triple_json(extent, 4)},
      {"heading_deg", json_number(o.heading_deg, 5)},
  };
  members.insert(members.end(), rest.begin(), rest.end());
  return members;
}

std::string members_json(const std::vector<JsonMember>& members) {
  std::string s = "{";
  for (const JsonMember& m : members) s += (s.size() > 1 ? "," : "") + json_string(m.key) + ":" + m.value;
  return s + "}";
}

std::string object_json(const std::string& tile, uint32_t k, const Database& db, const SceneObject& o,
                        const std::string& crs, double time_ms) {
  std::vector<JsonMember> members = object_members(tile, k, db, o);
  members.push_back({"crs", crs.empty() ? std::string("null") : json_string(crs)});
  members.push_back({"time_ms", json_number(time_ms, 6)});
  members.push_back({"version", json_string(version())});
  return members_json(members);
}

}  // namespace spinhash::pipeline
