#include "pipeline/scene_session.hpp"

#include <chrono>

namespace spinhash::pipeline {

bool SceneSession::init(const Database* db, const SceneConfig& cfg, std::string* error) {
  SceneConfig probe = cfg;
  if (probe.max_tile_points == 0) probe.max_tile_points = 1;  // 0: sized from each tile's density
  if (!scene_config_valid(probe)) {
    *error = "invalid scene configuration";
    return false;
  }
  db_ = db;
  config_ = cfg;
  tile_.reset();
  return true;
}

void SceneSession::push(const double* xyz, size_t n) {
  if (!tile_) {
    TileStreamOptions options;
    options.scene = config_;
    tile_ = std::make_unique<TileStreamer>(options);
    started_ = std::chrono::steady_clock::now();
  }
  tile_->add(xyz, n);
}

SceneResult SceneSession::flush() {
  if (!tile_) push(nullptr, 0);
  objects_.clear();
  rankings_.clear();
  uint32_t dropped = 0;
  last_ = tile_->finish(*db_, [&](const SceneObject& o) {
    if (objects_.size() >= config_.max_objects) {
      ++dropped;
      return;
    }
    objects_.push_back(o);
    rankings_.emplace_back(o.ranking, o.ranking + o.ranking_count);
  });
  tile_.reset();
  last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_).count();
  for (size_t k = 0; k < objects_.size(); ++k) objects_[k].ranking = rankings_[k].data();
  SceneResult r;
  r.status = last_.status;
  if (dropped > 0 && r.status == Status::kOk) r.status = Status::kTooManyObjects;
  r.objects = objects_.data();
  r.object_count = static_cast<uint32_t>(objects_.size());
  r.stats = last_.stats.scene;
  r.stats.objects_dropped += dropped;
  r.stats.workspace_used = last_.workspace_bytes;
  r.points_lost = last_.stats.points_outside + last_.stats.points_late + last_.stats.points_glitch +
                  last_.stats.points_overflow;
  return r;
}

SceneResult SceneSession::recognize(const std::vector<double>& xyz) {
  tile_.reset();
  push(xyz.data(), xyz.size() / 3);
  return flush();
}

std::string scene_stats_text(const SceneStats& st) {
  std::string s = "points " + std::to_string(st.points_in) + ", non-finite " +
                  std::to_string(st.points_nonfinite) + ", ground " + std::to_string(st.points_ground) +
                  ", in objects " + std::to_string(st.points_in_objects) + ", fragments " +
                  std::to_string(st.points_fragments);
  if (st.points_low_noise)
    s += ", low noise " + std::to_string(st.points_low_noise) + " (under the terrain, left out of it)";
  s += "; terrain " + std::to_string(st.terrain_cells) + " cells x " + std::to_string(st.terrain_windows) +
       " windows; segmentation " + std::to_string(st.segment_cells) + " cells, " +
       std::to_string(st.components) + " components; objects:";
  for (uint32_t k = 0; k < kObjectKinds; ++k)
    s += std::string(k ? ", " : " ") + object_kind_name(static_cast<ObjectKind>(k)) + " " +
         std::to_string(st.objects_by_kind[k]);
  if (st.objects_dropped) s += ", dropped " + std::to_string(st.objects_dropped);
  s += "; recognition: " + std::to_string(st.recognition_candidates) + " candidates, " +
       std::to_string(st.recognition_hypotheses) + " hypotheses";
  if (st.objects_out_of_work)
    s += ", " + std::to_string(st.objects_out_of_work) + " candidates not recognised (window work spent)";
  return s;
}

}  // namespace spinhash::pipeline
