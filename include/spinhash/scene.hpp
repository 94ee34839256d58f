// The scene recognizer: an airborne lidar tile in (georeferenced xyz, z up),
// one answer per object out. Terrain (geometry/terrain.hpp), objects
// (scene/segment.hpp), size gates, then the Recognizer on each vehicle-sized
// object. The tile API runs the stream's path (scene_stream.hpp) over a
// tile held in memory, ordered along track band by band as every host front
// end orders a file (scene_tile.hpp): the same windows and answers. No
// heap: every buffer comes from the caller's workspace, sized by
// required_scene_workspace_bytes(config).
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>

#include "spinhash/recognizer.hpp"

namespace spinhash {

enum class ObjectKind : uint8_t {
  kVehicleCandidate = 0,  // within the vehicle size gates: recognised
  kTooSmall = 1,          // shorter or lower than a vehicle, or few points (crates, posts, trunks)
  kTooLarge = 2,          // longer or wider than a vehicle (buildings)
  kNotVehicleShaped = 3,  // thin (walls), tall (trees) or floating high above the terrain (crowns)
  kUnknown = 4,           // vehicle-sized but recognition failed
};
constexpr uint32_t kObjectKinds = 5;

const char* object_kind_name(ObjectKind k) noexcept;

struct SceneConfig {
  // Recognition of each vehicle candidate. Its ground_clearance is not used:
  // objects reach the recognizer without their ground.
  RecognizerConfig recognizer{};
  uint32_t top_n = 5;  // ranking entries kept per object

  // Windows (scene_stream.hpp): square cores of window_core m tile the
  // ground. A window's terrain sees window_margin m more on every side: half
  // the longest vehicle (max_length / 2 = 6.5 m) plus the terrain filter's
  // reach (its openings add up to 31 m at a 24 m window, 33 m after the
  // low-noise test's two passes of 1 m): 40 m. Its objects
  // are segmented from object_margin m around the core: an object whose
  // centre is in the core and that the margin cuts spans at least twice the
  // margin, so at least hypot(max_length, max_width) (13.6 m) gates it out
  // as too large; a vehicle is always whole (7 m: 2 x 7 > 13.6). The core and both margins are
  // multiples of terrain_cell (and the core of segment_cell), so overlapping
  // windows share their grid cells. A window gathers (32 + 14)^2 m, 2.1x
  // its core: 32 m cores keep the stream's buffer a third smaller than 64 m
  // ones for the same answers and less work.
  float window_core = 32.0f;    // m
  float window_margin = 40.0f;  // m
  float object_margin = 7.0f;   // m

  // Capacities of one window (the tile path sizes the stream's buffer from
  // max_tile_points: scene_tile.hpp).
  uint32_t max_tile_points = 1u << 21;  // points a window holds (more: kWindowOverflow, counted)
  uint32_t max_objects = 256;           // objects of >= min_object_points points per window
  // Work units (RecognizerConfig::max_work's) a window's recognitions
  // share, in the order the window finds its objects: each gets at most
  // what the earlier ones left, and once it is spent the rest are not
  // recognised (status kWorkCapReached). 0: each object has its own
  // max_work alone, and a window's work is bounded only by max_objects of
  // them. Bounds a flight line's worst window (docs/budgets.md).
  uint64_t window_max_work = 0;
  uint32_t max_terrain_cells =
      1u << 17;  // terrain grid: 0.5 m cells; windows of a row share it (2 of 64 + 40 m)
  uint32_t max_segment_cells = 1u << 19;  // segmentation grid: 0.25 m cells -> 181 x 181 m

  // Terrain (progressive morphological filter).
  float terrain_cell = 0.5f;      // m
  float terrain_window = 24.0f;   // m: widest opening (wider than the buildings to lift off)
  float terrain_slope = 0.35f;    // rise per m between windows (0.35: terrain to ~19 degrees)
  float terrain_dh0 = 0.2f;       // m
  float terrain_dh_max = 2.5f;    // m
  float ground_height = 0.25f;    // m above the terrain that is still ground
  float terrain_low_band = 0.3f;  // m: a cell's value is the mean of its points this close to its lowest:
                                  // unbiased on slopes (the lowest sits downhill), steadier under noise
  // Low noise (multipath returns under the ground, unclassified): a cell's
  // lowest point more than terrain_noise_gap under the cell's next point is
  // left out of the terrain unless terrain_noise_support of the cells within
  // terrain_noise_reach that hold points (or a quarter of them, where that
  // is fewer) have a lowest less than the gap above it. Such a pit survives the openings and,
  // where pits lie closer than the widest window, pulls the whole terrain
  // down; a true ground point left out (under a crown) only makes its cell a
  // bump the filter lifts.
  float terrain_noise_gap = 1.0f;      // m (0: off): above curbs and a cell's slope, below multipath depths
  float terrain_noise_reach = 1.0f;    // m: the ground around; holds a dozen points at 2 points per m2
  uint32_t terrain_noise_support = 2;  // two pits at one depth are noise; a floor or a ditch has more

  // Segmentation: 8-connected cells. Points up to layer_split_height above
  // the terrain form the low layer (vehicles; the empty gap between parked
  // cars splits them); points above it the high layer (tree crowns, roofs),
  // so a crown over a car never joins it.
  float segment_cell = 0.25f;       // m: must be below the narrowest gap to split (0.5 m)
  float layer_split_height = 3.8f;  // m: above the tallest vehicle (buses 3.5 m), below most crowns
  uint32_t min_object_points = 30;  // smaller components are noise, not objects
  // A cell's column in height bins of column_bin (kSegmentColumnBins of
  // them): an empty gap of layer_gap (a multiple of the bin) parts the low
  // layer from what is above it (a crown over a car's roof).
  float column_bin = 0.25f;  // m
  float layer_gap = 1.0f;    // m: more than a vehicle's own gaps (windows, roof racks)

  // Size gates (footprint along the object's principal axes; heights above terrain).
  float min_length = 2.2f, max_length = 13.0f;  // m: buses reach 12 m
  float min_width = 1.1f, max_width = 4.0f;     // m: tracked vehicles 3.6 m
  float min_height = 0.9f, max_height = 4.5f;   // m: highest point above the terrain
  float max_clearance = 1.2f;                   // m: lowest point above the terrain; higher floats (crowns)
  float max_size_mismatch = 0.15f;              // confident only if the object's length and width are
                                                // within this share of the best model's bounding box
  float class_size_factor = 2.0f;               // a confident class: its leader's box within this many times
                                                // max_size_mismatch (members of a class differ by decimetres,
                                                // classes by metres)
  // Confident only if the best model, under its pose, does not sink into the
  // terrain by more than this (m; SceneObject::ground_gap): a look-alike
  // taller than the scanned vehicle, posed to fit its roof, does (a bus
  // 0.28 m taller: 0.18-0.25 m deep). Right answers on simulated tiles lie
  // at -0.09 m and above; a model may float (a vehicle on a trailer, a model
  // without wheels, terrain estimated low under a vehicle on a slope).
  float max_ground_sink = 0.15f;

  // The tile path (this API and the host's files; SceneStream ignores
  // them): a tile runs in bands of band_columns window columns across, each
  // its own line, its rows of row_depth along x pushed in order (the
  // points of a row in any order: the stream's max_lag). Wider bands hold
  // more in the stream's buffer; deeper rows delay each row's windows.
  uint32_t band_columns = 2;
  float row_depth = 8.0f;  // m
};

struct SceneObject {
  ObjectKind kind = ObjectKind::kUnknown;
  Status status = Status::kOk;  // recognition status (kOk for objects not recognised)
  uint32_t points = 0;
  double center[3] = {0, 0, 0};  // georeferenced: the footprint's centre, z mid-height
  float extent[3] = {0, 0, 0};   // m: length, width along the principal axes; height above terrain
  float heading_deg = 0.0f;      // direction of the length axis, degrees from +x
  float min_height = 0.0f;       // m above the terrain (lowest point)
  bool high_layer = false;       // made of points above layer_split_height
  // Vehicle candidates only:
  const RankedModel* ranking = nullptr;  // in the workspace, best first; valid until the next call
  uint32_t ranking_count = 0;            // <= top_n
  bool confident = false;
  uint32_t group_size = 0;  // Result::group_size of its recognition (may exceed ranking_count)
  // The class level (Result::class_ranking; best_rank may exceed ranking_count).
  RankedClass classes[kVehicleClassCount] = {};
  uint32_t class_count = 0;
  bool class_confident = false;  // Result::class_confident and the class leader's size agrees
  // The group level (Result::group_ranking).
  RankedGroup groups[kVehicleGroupCount] = {};
  uint32_t group_count = 0;
  // Result::levels, with the model and class flags as `confident` and
  // `class_confident` (the size tests added), and the level they give
  // (Result::level).
  LevelAnswer levels[kCalibratedLevels] = {};
  AnswerLevel level = AnswerLevel::kNone;
  // The best model's bottom above the terrain under its pose, m (mean of its
  // box's four bottom corners; < 0: sunk into it); NaN without a ranking or
  // without terrain under it.
  float ground_gap = std::numeric_limits<float>::quiet_NaN();
  RecognitionStats stats;  // of its recognition
};

struct SceneStats {
  uint32_t points_in = 0;
  uint32_t points_nonfinite = 0;
  uint32_t points_ground = 0;
  uint32_t points_in_objects = 0;
  uint32_t points_fragments = 0;  // in components below min_object_points
  uint32_t points_low_noise = 0;  // ground more than terrain_noise_gap under the terrain: left out of it
  uint32_t terrain_cells = 0;
  uint32_t terrain_windows = 0;
  uint32_t segment_cells = 0;
  uint32_t components = 0;       // connected components, fragments included
  uint32_t objects_dropped = 0;  // past max_objects (status kTooManyObjects)
  uint32_t objects_by_kind[kObjectKinds] = {};
  uint32_t windows = 0;                 // windows run (those that gathered points)
  uint32_t windows_overflowed = 0;      // windows over a capacity: not recognised (kWindowOverflow)
  uint64_t recognition_hypotheses = 0;  // summed over the candidates
  uint64_t recognition_candidates = 0;
  uint64_t recognition_work = 0;     // work units of the candidates' recognitions
  uint32_t objects_out_of_work = 0;  // candidates not recognised: their window's window_max_work was spent
  size_t workspace_used = 0;
};

struct SceneResult {
  // kOk; kTooManyObjects with the first max_objects answered; kWindowOverflow
  // when a window held more points than max_tile_points, the stream's
  // buffer more than it holds, or a window more cells than its grids (its
  // objects are not answered; stats count them).
  Status status = Status::kNotOpen;
  const SceneObject* objects = nullptr;  // in the workspace; valid until the next call
  uint32_t object_count = 0;
  SceneStats stats;  // summed over the windows (points_in: each finite point once, by its window)
  // Finite points the stream did not take (StreamStats: beyond
  // kMaxStreamExtent of the tile's lowest corner, unconfirmed jumps, past
  // the buffer).
  uint64_t points_lost = 0;
};

struct SceneBuffers;  // the workspace layout (firmware-lib/scene)

// Workspace bytes SceneRecognizer::init needs (0 for an invalid config).
size_t required_scene_workspace_bytes(const SceneConfig& config) noexcept;
bool scene_config_valid(const SceneConfig& config) noexcept;

class SceneRecognizer {
 public:
  Status init(const Database* db, const SceneConfig& config, void* workspace,
              size_t workspace_bytes) noexcept;
  // n points of xyz (x0 y0 z0 x1 ...), georeferenced, z up, in any order and
  // of any extent, through the stream's windows (scene_tile.hpp), each
  // object reported once. Non-finite points are skipped and counted.
  SceneResult recognize(const double* xyz, uint32_t n) noexcept;
  size_t used_bytes() const noexcept { return used_bytes_; }

 private:
  const Database* db_ = nullptr;
  SceneConfig config_{};
  size_t used_bytes_ = 0;
  SceneBuffers* buffers_ = nullptr;
};

}  // namespace spinhash
