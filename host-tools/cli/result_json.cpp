#include "cli/result_json.hpp"

#include "cli/json_line.hpp"
#include "cli/report_keys.hpp"
#include "pipeline/class_json.hpp"
#include "pipeline/level_json.hpp"
#include "pipeline/object_json.hpp"
#include "pipeline/recognition_session.hpp"
#include "pipeline/status_word.hpp"
#include "spinhash/answered.hpp"
#include "spinhash/config_fields.h"

namespace spinhash::cli {

using pipeline::model_name;
using pipeline::pose_json;

const char* status_word(Status s) { return pipeline::status_word(s); }

namespace {

std::string stat_json(bool v) { return v ? "true" : "false"; }
std::string stat_json(uint32_t v) { return std::to_string(v); }
std::string stat_json(uint64_t v) { return std::to_string(v); }
std::string stat_json(float v) { return json_number(static_cast<double>(v), 4); }

// Every entry of SPINHASH_STATS_FIELDS, under its JSON key.
std::string stats_json(const RecognitionStats& st) {
  std::string s;
#define SPINHASH_STAT_JSON(kind, name, member, json) \
  s += std::string(s.empty() ? "{" : ",") + "\"" json "\":" + stat_json(st.member);
  SPINHASH_STATS_FIELDS(SPINHASH_STAT_JSON)
#undef SPINHASH_STAT_JSON
  return s + "}";
}

}  // namespace

std::string result_json(const std::string& query, const Database& db, const Result& r, uint32_t top,
                        double time_ms, const std::string& crs) {
  std::string s = "{\"query\":" + json_string(query) + ",\"status\":" + json_string(status_word(r.status));
  if (r.status != Status::kOk) s += ",\"error\":" + json_string(status_name(r.status));
  s += ",\"ranking\":[";
  uint32_t n = top == 0 || top > r.ranking_count ? r.ranking_count : top;
  for (uint32_t i = 0; i < n; ++i) {
    if (i > 0) s += ",";
    s += "{\"model\":" + json_string(model_name(db, r.ranking[i].model)) +
         ",\"score\":" + json_number(static_cast<double>(r.ranking[i].score), 7) + "}";
  }
  s += "],\"pose\":";
  s += r.ranking_count > 0 && r.ranking[0].has_pose ? pose_json(r.ranking[0].pose) : std::string("null");
  s += std::string(",\"confident\":") + (r.confident ? "true" : "false");
  s += ",\"group_size\":" + std::to_string(has_answer(r.status) ? r.group_size : 0u);
  const bool ok = has_answer(r.status);
  s += "," +
       pipeline::class_json(db, r.class_ranking, ok ? r.class_ranking_count : 0u, ok && r.class_confident);
  s += "," + pipeline::level_json(db, pipeline::level_view(r));
  s += ",\"crs\":" + (crs.empty() ? std::string("null") : json_string(crs));
  s += ",\"time_ms\":" + json_number(time_ms, 4) +
       ",\"hypotheses\":" + std::to_string(r.stats.draws.hypotheses);
  s += ",\"stats\":" + stats_json(r.stats) + "," + json_version_member() + "}";
  return s;
}

}  // namespace spinhash::cli
