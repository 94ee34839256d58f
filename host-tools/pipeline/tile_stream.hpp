// A tile of any size and point order through the SceneStream in bounded
// memory, on the core's tile plan (spinhash/scene_tile.hpp), the one path
// of `spinhash scene`, the survey, Python's SceneRecognizer and the
// experiments. The points go through an AlongTrackOrder (rows of row_depth
// along x, columns of a window core across y: tile_stream_order.hpp), which
// also learns the tile's extent and density; then each band of columns
// whose windows gather points is streamed as a line of its own
// (SceneStream::reset with the band's origin), its rows in order. Each
// object is reported once, by the window whose core owns its centre; a
// survey's tile keeps only what it owns among its neighbours
// (scene_ownership.hpp). Memory: the stream's workspace, sized from the
// tile's density over one band (never the tile's width or length), the
// order's memory budget and the picture's sample.
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cloud/crs_units.hpp"
#include "cloud/point_source.hpp"
#include "pipeline/tile_stream_order.hpp"
#include "spinhash/scene_ownership.hpp"
#include "spinhash/scene_stream.hpp"

namespace spinhash::pipeline {

struct TileStreamOptions {
  SceneConfig scene;                 // window stages; max_tile_points 0: sized from the density
  uint64_t max_buffered_points = 0;  // 0: sized from the tile's density
  size_t chunk_points = host::kDefaultChunkPoints;
  // Points the along-track order holds before it spills to a temporary file
  // (12 B each); the answers do not depend on it.
  size_t order_memory_points = kOrderMemoryPoints;
  uint32_t picture_points = 0;  // keep an even sample of about this many points for a picture (0: none)
  // scene.segment_cell is the finest cell, grown to the tile's point spacing
  // (segment_cell.hpp); false: used as it is (a survey decides it once).
  bool segment_cell_from_density = true;
  // A survey's tile among its neighbours (in the file's units): an object is
  // reported only when owner_of(owners, its centre, owner_tolerance) is
  // `self`; the others are counted. Empty: every object is the tile's.
  std::vector<OwnedArea> owners;
  uint32_t self = 0;
  double owner_tolerance = 0.0;
  // The file's units (cloud/crs_units.hpp): points are scaled to metres on
  // reading; objects (pipeline/object_units.hpp), owners and the picture's
  // points are in the file's units.
  host::AxisUnits units;
};

struct TileStreamResult {
  Status status = Status::kNotOpen;
  StreamStats stats;  // summed over the bands (points_pushed: the points read, once)
  uint64_t points_read = 0;
  size_t workspace_bytes = 0;
  double density = 0.0;            // points per m2 of what the tile covers (segment_cell.hpp)
  float segment_cell = 0.0f;       // m: the segmentation cell the tile was streamed with
  uint32_t bands = 0;              // bands streamed: those whose windows gather points
  uint64_t objects_not_owned = 0;  // centres a neighbour owns
  uint64_t objects_in_holes = 0;   // centres no tile owns
  double read_ms = 0.0, stream_ms = 0.0;
  std::vector<double> picture_xyz;  // an even sample of the tile, when asked
};

using ObjectCallback = std::function<void(const SceneObject&)>;

// An even sample of at most about twice `target` of the points that pass,
// whatever their number: every k-th point, k doubling (and every other kept
// point dropped) when the sample outgrows it. expected: the declared count
// (0: unknown), to start at the right k.
class PointSample {
 public:
  PointSample(uint32_t target, uint64_t expected);
  void add(const double* p);
  const std::vector<double>& xyz() const { return xyz_; }
  std::vector<double> take() { return std::move(xyz_); }

 private:
  uint64_t target_, every_ = 1, seen_ = 0;
  std::vector<double> xyz_;
};

// A tile handed over in chunks of any size and order (points in metres),
// then streamed once.
class TileStreamer {
 public:
  // expected_points: the declared count (0: unknown), for the picture's sample.
  explicit TileStreamer(const TileStreamOptions& options, uint64_t expected_points = 0);
  // Throws std::runtime_error when the order's temporary file cannot be written.
  void add(const double* xyz, size_t n);
  // Streams the tile; objects go to on_object as their windows complete.
  // Throws std::runtime_error for a configuration no stream takes.
  TileStreamResult finish(const Database& db, const ObjectCallback& on_object);

 private:
  TileStreamOptions options_;
  AlongTrackOrder order_;
  PointSample picture_;
  uint64_t added_ = 0;
  std::chrono::steady_clock::time_point start_;
};

// Reads the source through a TileStreamer; throws host::CloudError for a
// malformed file (objects already reported stay reported) and
// std::runtime_error when the temporary file cannot be written.
TileStreamResult stream_tile(const Database& db, host::PointSource& source, const TileStreamOptions& options,
                             const ObjectCallback& on_object);

}  // namespace spinhash::pipeline
