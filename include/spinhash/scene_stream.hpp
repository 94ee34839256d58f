// The streaming scene recognizer: a flight line of any length in fixed
// memory. The scene's stages (terrain, objects, size gates, recognition:
// scene.hpp) run on square windows whose cores tile the ground and whose
// margins see every vehicle whole; each object is reported once, by the
// window whose core owns its centre (scene_ownership.hpp), as soon as that
// window is complete. Work follows the points: rows of windows where no
// point lies are skipped, whatever the distance between points.
//
// The ordering contract: points come in chunks of any size, in along-track
// order up to a lag of StreamConfig::max_lag (scan order is). A point more
// than max_lag behind the furthest point pushed may find its terrain or its
// windows done: it is dropped, counted (StreamStats::points_late), and the
// push returns kPointsLate, which the caller cannot take for kOk. Points in
// any other order (a file's chunks, a tile cut in pieces) go through an
// along-track ordering first: the tile API (scene.hpp) orders a tile held
// in memory; on a host, the library's AlongTrackOrder
// (host-tools/pipeline/tile_stream_order.hpp, Python's spinhash.AlongTrackOrder
// and SceneRecognizer.push) orders any stream of chunks in bounded memory.
//
// The frame: s along track (heading_deg from +x, counter-clockwise), t
// across, both from the origin (the first finite point unless given).
// Window (k, j) owns s in [k core, (k+1) core) and t in [own_min + j core,
// own_min + (j+1) core) (core: SceneConfig::window_core) within [own_min,
// own_max): a centre exactly on an edge belongs to the window whose core
// starts there. The centre that decides is the object's footprint box
// centre taken from its points' exact stream coordinates, so overlapping
// windows agree on it bit for bit.
//
// Memory: a buffer of max_buffered_points points (12 B each: 1 mm steps)
// awaiting their windows, plus one window's working set
// (scene.max_tile_points points): required_stream_workspace_bytes(config),
// whatever the line's length.
#pragma once
#include <cstddef>
#include <cstdint>

#include "spinhash/scene.hpp"

namespace spinhash {

struct StreamConfig {
  SceneConfig scene{};  // each window's stages; scene.max_tile_points is a window's capacity

  // The frame.
  bool origin_given = false;  // else the first finite point pushed
  double origin[3] = {0, 0, 0};
  float heading_deg = 90.0f;  // along-track direction, degrees from +x (90: north)

  // The swath across track (m from the origin): points outside it are
  // counted (points_outside) and dropped; the owned band lies within it.
  float swath_min = -128.0f, swath_max = 128.0f;
  float own_min = -128.0f, own_max = 128.0f;

  // Order. A point more than max_lag behind the furthest along-track point
  // seen may find its window done (then it is counted as late). A point
  // more than max_jump ahead is a glitch (a GNSS jump) unless the next
  // jump_confirm_points points confirm it (a gap in the data).
  float max_lag = 16.0f;              // m
  float max_jump = 500.0f;            // m
  uint32_t jump_confirm_points = 16;  // a gap has many points behind it; a glitch, a few
  float max_z_offset = 3000.0f;       // m: |z - origin z| beyond this is an outlier (counted)

  uint32_t max_buffered_points = 1u << 23;  // points held awaiting their windows (12 B each)
};

struct StreamStats {
  SceneStats scene;  // summed over the windows (points_in: points pushed)
  uint64_t points_pushed = 0;
  uint64_t points_outside = 0;   // outside the swath across track, or beyond max_z_offset
  uint64_t points_late = 0;      // arrived after their window was done (push: kPointsLate)
  uint64_t points_glitch = 0;    // along-track jumps that were not confirmed
  uint64_t points_overflow = 0;  // the buffer was full: dropped
  uint64_t points_after_flush = 0;
  uint64_t windows = 0;             // windows run (empty ones are skipped)
  uint64_t windows_overflowed = 0;  // more points than a window holds: not recognised
  uint64_t points_in_overflowed = 0;
  uint64_t objects_reported = 0;
  uint64_t objects_not_owned = 0;  // seen in a window that did not own them (another did)
  double furthest_along = 0.0;     // m: the furthest along-track point taken
  double done_until = 0.0;         // m: every window before this along track is reported
};

// Called once per reported object; `object` and its ranking are valid only
// during the call. window_row / window_col: the owning window.
using SceneObjectSink = void (*)(void* context, const SceneObject& object, int64_t window_row,
                                 uint32_t window_col);

struct StreamBuffers;  // the workspace layout (firmware-lib/scene)

size_t required_stream_workspace_bytes(const StreamConfig& config) noexcept;
bool stream_config_valid(const StreamConfig& config) noexcept;

// Adds one line's counts to a total (several lines, a tile's bands): counts
// add (32-bit ones stop at their top), positions along the line and the
// workspace take the largest.
void add_stream_stats(StreamStats& into, const StreamStats& line) noexcept;

class SceneStream {
 public:
  Status init(const Database* db, const StreamConfig& config, void* workspace, size_t workspace_bytes,
              SceneObjectSink sink, void* sink_context) noexcept;
  // n points of xyz (x0 y0 z0 x1 ...), georeferenced, z up, in the order
  // of the contract above. Windows that become complete run inside the
  // call and report to the sink. kOk, or kPointsLate (points behind the
  // declared lag were dropped: stats().points_late), kWindowOverflow (some
  // points or a window's objects were lost: counted in stats()),
  // kTooManyObjects, kStreamFlushed (nothing taken), kNotOpen.
  [[nodiscard]] Status push(const double* xyz, uint32_t n) noexcept;
  // Ends the line: runs every window still pending. Later pushes are
  // refused until reset().
  [[nodiscard]] Status flush() noexcept;
  // Starts a new line (same config and workspace): stats and buffer
  // cleared. With an origin (x y z), the frame's origin from now on (a
  // tile's next band), else the config's.
  void reset(const double* origin = nullptr) noexcept;
  const StreamStats& stats() const noexcept;
  size_t used_bytes() const noexcept { return used_bytes_; }

 private:
  StreamBuffers* buffers_ = nullptr;
  size_t used_bytes_ = 0;
};

}  // namespace spinhash
