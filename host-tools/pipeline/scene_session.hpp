// A SceneRecognizer with a heap-allocated workspace of exactly the required
// size: the host-side way to recognise whole tiles.
#pragma once
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::pipeline {

class SceneSession {
 public:
  // false with a message when the config is invalid or does not fit the database.
  bool init(const Database* db, const SceneConfig& cfg, std::string* error);
  SceneResult recognize(const std::vector<double>& xyz);
  double last_ms() const { return last_ms_; }  // wall time of the last recognize()
  size_t workspace_bytes() const { return workspace_.size(); }

 private:
  host::AlignedBytes workspace_;
  SceneRecognizer scene_;
  double last_ms_ = 0.0;
};

// One line of per-tile statistics (points, ground, objects by kind, stage work).
std::string scene_stats_text(const SceneStats& st);

}  // namespace spinhash::pipeline
