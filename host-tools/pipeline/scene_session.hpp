// The host's tile API: a tile in memory, or handed over in chunks of any
// order, through the one scene path of `spinhash scene` (tile_stream.hpp),
// so that Python's SceneRecognizer and the experiments answer as the
// command does, in bounded memory.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/tile_stream.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::pipeline {

class SceneSession {
 public:
  // false with a message when the config is invalid.
  bool init(const Database* db, const SceneConfig& cfg, std::string* error);
  // Adds points (x y z, metres) of the tile being gathered, in any order.
  void push(const double* xyz, size_t n);
  // Recognises the points pushed since the last flush: the tile's objects,
  // at most max_objects (the rest dropped: kTooManyObjects), valid until
  // the next flush or recognize.
  SceneResult flush();
  // push then flush.
  SceneResult recognize(const std::vector<double>& xyz);
  const TileStreamResult& last() const { return last_; }  // the stream's account of the last tile
  double last_ms() const { return last_ms_; }             // wall time of the last flush (push included)
  size_t workspace_bytes() const { return last_.workspace_bytes; }

 private:
  const Database* db_ = nullptr;
  SceneConfig config_;
  std::unique_ptr<TileStreamer> tile_;
  std::chrono::steady_clock::time_point started_;
  std::vector<SceneObject> objects_;
  std::vector<std::vector<RankedModel>> rankings_;
  TileStreamResult last_;
  double last_ms_ = 0.0;
};

// One line of per-tile statistics (points, ground, objects by kind, stage work).
std::string scene_stats_text(const SceneStats& st);

}  // namespace spinhash::pipeline
