#include "pipeline/scene_session.hpp"

#include <chrono>

namespace spinhash::pipeline {

bool SceneSession::init(const Database* db, const SceneConfig& cfg, std::string* error) {
  const size_t bytes = required_scene_workspace_bytes(cfg);
  if (bytes == 0) {
    *error = "invalid scene configuration";
    return false;
  }
  workspace_ = host::AlignedBytes(bytes);
  const Status s = scene_.init(db, cfg, workspace_.data(), workspace_.size());
  if (s != Status::kOk) {
    *error = std::string("scene recognizer: ") + status_name(s);
    return false;
  }
  return true;
}

SceneResult SceneSession::recognize(const std::vector<double>& xyz) {
  const auto start = std::chrono::steady_clock::now();
  const uint64_t n = xyz.size() / 3u;
  SceneResult r;
  if (n > 0xFFFFFFFFull)
    r.status = Status::kTooManyPoints;  // more than any workspace holds
  else
    r = scene_.recognize(xyz.data(), static_cast<uint32_t>(n));
  last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::string scene_stats_text(const SceneStats& st) {
  std::string s = "points " + std::to_string(st.points_in) + ", non-finite " +
                  std::to_string(st.points_nonfinite) + ", ground " + std::to_string(st.points_ground) +
                  ", in objects " + std::to_string(st.points_in_objects) + ", fragments " +
                  std::to_string(st.points_fragments) + "; terrain " + std::to_string(st.terrain_cells) +
                  " cells x " + std::to_string(st.terrain_windows) + " windows; segmentation " +
                  std::to_string(st.segment_cells) + " cells, " + std::to_string(st.components) +
                  " components; objects:";
  for (uint32_t k = 0; k < kObjectKinds; ++k)
    s += std::string(k ? ", " : " ") + object_kind_name(static_cast<ObjectKind>(k)) + " " +
         std::to_string(st.objects_by_kind[k]);
  if (st.objects_dropped) s += ", dropped " + std::to_string(st.objects_dropped);
  s += "; recognition: " + std::to_string(st.recognition_candidates) + " candidates, " +
       std::to_string(st.recognition_hypotheses) + " hypotheses";
  return s;
}

}  // namespace spinhash::pipeline
