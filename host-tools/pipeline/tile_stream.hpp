// A tile of any size and point order through the SceneStream in bounded
// memory. One pass over the file's chunks spills the points to temporary
// files, one per 32 m cell of the window lattice (absolute multiples of the
// core, so the windows of adjacent tiles line up), and finds the tile's
// extent. Then the tile is streamed in bands of 2 columns (64 m) across,
// each a stream that owns its columns and sees 40 m margins beyond them:
// rows pushed in order (lag at most one row), each object reported once.
// Memory: the stream's workspace, sized from the tile's density over one
// band (never the tile's width or length), the readers' chunks and the
// cells' write buffers (24 KB each).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cloud/crs_units.hpp"
#include "cloud/point_source.hpp"
#include "spinhash/scene_stream.hpp"

namespace spinhash::pipeline {

struct TileStreamOptions {
  SceneConfig scene;                 // window stages; max_tile_points 0: sized from the density
  uint64_t max_buffered_points = 0;  // 0: sized from the tile's width and density
  size_t chunk_points = host::kDefaultChunkPoints;
  uint32_t picture_points = 0;  // keep about this many points for a picture (0: none)
  // A survey's tile with its neighbours' buffer: only objects whose centre
  // lies in [own_min, own_max) (x, y; half-open) are reported, the others
  // counted in objects_not_owned (a neighbour reports them).
  bool own_given = false;
  double own_min[2] = {0, 0}, own_max[2] = {0, 0};  // in the file's units
  // The file's units (cloud/crs_units.hpp): points are scaled to metres on
  // reading; objects (pipeline/object_units.hpp), own_* and the picture's
  // points are in the file's units.
  host::AxisUnits units;
};

struct TileStreamResult {
  Status status = Status::kNotOpen;
  StreamStats stats;
  uint64_t points_read = 0;
  size_t workspace_bytes = 0;
  uint32_t bands = 0;
  uint64_t objects_not_owned = 0;  // centres outside options.own_* (a neighbour's)  // bands of 2 columns (64
                                   // m) across, each its own stream
  double read_ms = 0.0, stream_ms = 0.0;
  std::vector<double> picture_xyz;  // an even sample of the tile, when asked
};

using ObjectCallback = std::function<void(const SceneObject&)>;

// Runs the tile; throws host::CloudError for a malformed file (objects
// already reported stay reported) and std::runtime_error when the temporary
// files cannot be written.
TileStreamResult stream_tile(const Database& db, host::PointSource& source, const TileStreamOptions& options,
                             const ObjectCallback& on_object);

}  // namespace spinhash::pipeline
