// SceneRecognizer: tile -> terrain -> objects -> size gates -> Recognizer per
// vehicle candidate. The workspace layout is carved by one function, run in
// counting mode for required_scene_workspace_bytes().
#include "spinhash/scene.hpp"

#include <cmath>
#include <limits>
#include <new>

#include "geometry/terrain.hpp"
#include "scene/segment.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {

constexpr uint32_t kMaxSceneTopN = 64;  // ranking entries kept per object
constexpr uint32_t kMaxSceneObjects = 1u << 16;
constexpr uint32_t kMaxSceneTilePoints = 1u << 26;
constexpr uint32_t kMaxSceneGridCells = 1u << 24;

struct SceneBuffers {
  Recognizer recognizer;
  float* local = nullptr;   // 3 x max_tile_points: finite points relative to the origin
  float* height = nullptr;  // above the terrain
  uint8_t* ground = nullptr;
  uint32_t* label = nullptr;
  float* gathered = nullptr;    // 3 x max_tile_points: points sorted by object
  uint32_t* offsets = nullptr;  // max_objects + 1
  ObjectShape* shapes = nullptr;
  SceneObject* objects = nullptr;
  RankedModel* rankings = nullptr;  // max_objects x top_n
  TerrainGrid terrain;
  SegmentGrid segments;
};

namespace {

RecognizerConfig object_config(const SceneConfig& c) {
  RecognizerConfig r = c.recognizer;
  r.ground_clearance = 0.0f;  // the scene removed the ground already, on any slope
  return r;
}

TerrainParams terrain_params(const SceneConfig& c) {
  TerrainParams p;
  p.cell = c.terrain_cell;
  p.max_window = c.terrain_window;
  p.slope = c.terrain_slope;
  p.dh0 = c.terrain_dh0;
  p.dh_max = c.terrain_dh_max;
  p.ground_height = c.ground_height;
  return p;
}

bool gates_valid(const SceneConfig& c) {
  auto range = [](float lo, float hi) { return lo >= 0.0f && hi >= lo && hi <= 1000.0f; };
  return range(c.min_length, c.max_length) && range(c.min_width, c.max_width) &&
         range(c.min_height, c.max_height) && c.max_clearance >= 0.0f && c.max_clearance <= 1000.0f &&
         c.max_size_mismatch >= 0.0f && c.max_size_mismatch <= 10.0f && c.max_ground_sink >= 0.0f &&
         c.segment_cell >= 0.02f && c.segment_cell <= 10.0f && c.layer_split_height > 0.0f &&
         c.layer_split_height <= 1000.0f;
}

Status carve(Arena& arena, const SceneConfig& c, SceneBuffers& b) {
  const size_t np = c.max_tile_points;
  b.local = arena.alloc<float>(3u * np);
  b.height = arena.alloc<float>(np);
  b.ground = arena.alloc<uint8_t>(np);
  b.label = arena.alloc<uint32_t>(np);
  b.gathered = arena.alloc<float>(3u * np);
  b.offsets = arena.alloc<uint32_t>(c.max_objects + 1u);
  b.shapes = arena.alloc<ObjectShape>(c.max_objects);
  b.objects = arena.alloc<SceneObject>(c.max_objects);
  b.rankings = arena.alloc<RankedModel>(static_cast<size_t>(c.max_objects) * c.top_n);
  b.terrain.carve(arena, c.max_terrain_cells);
  b.segments.carve(arena, c.max_segment_cells);
  return arena.overflowed() ? Status::kWorkspaceTooSmall : Status::kOk;
}

ObjectKind classify(const ObjectShape& o, const SceneConfig& c) {
  if (o.hmin > c.max_clearance) return ObjectKind::kNotVehicleShaped;  // crown, overhang
  if (o.length() > c.max_length || o.width() > c.max_width)
    return o.width() < c.min_width ? ObjectKind::kNotVehicleShaped
                                   : ObjectKind::kTooLarge;         // wall : building
  if (o.hmax > c.max_height) return ObjectKind::kNotVehicleShaped;  // tree
  if (o.length() < c.min_length || o.hmax < c.min_height) return ObjectKind::kTooSmall;
  if (o.width() < c.min_width) return ObjectKind::kNotVehicleShaped;  // short wall, fence
  return ObjectKind::kVehicleCandidate;
}

// A confident answer must also be the right size: the object's footprint
// within max_size_mismatch of the model's bounding box (length and width).
bool size_agrees(const ObjectShape& o, const blob::ModelRecord& m, float tolerance) {
  const float dx = m.bbox_max[0] - m.bbox_min[0], dy = m.bbox_max[1] - m.bbox_min[1];
  const float len = dx > dy ? dx : dy, wid = dx > dy ? dy : dx;
  return std::fabs(o.length() - len) <= tolerance * len && std::fabs(o.width() - wid) <= tolerance * wid;
}

// The model's box bottom above the terrain under `pose` (tile-local), m:
// the mean over its four bottom corners that have terrain under them; NaN
// when none has.
float ground_gap(const Pose& pose, const blob::ModelRecord& m, const TerrainGrid& terrain) {
  float sum = 0.0f;
  uint32_t corners = 0;
  for (int i = 0; i < 4; ++i) {
    const float c[3] = {i & 1 ? m.bbox_max[0] : m.bbox_min[0], i & 2 ? m.bbox_max[1] : m.bbox_min[1],
                        m.bbox_min[2]};
    float x[3];
    for (int r = 0; r < 3; ++r)
      x[r] = pose.rotation[3 * r] * c[0] + pose.rotation[3 * r + 1] * c[1] + pose.rotation[3 * r + 2] * c[2] +
             static_cast<float>(pose.translation[r]);
    const float ground = terrain_height_at(terrain, x[0], x[1]);
    if (!std::isfinite(ground)) continue;
    sum += x[2] - ground;
    ++corners;
  }
  return corners > 0 ? sum / static_cast<float>(corners) : std::numeric_limits<float>::quiet_NaN();
}

// Not sunk deeper than `tolerance`; NaN (no terrain to test against) passes.
bool not_sunk(float gap, float tolerance) { return !(gap < -tolerance); }

}  // namespace

const char* object_kind_name(ObjectKind k) noexcept {
  switch (k) {
    case ObjectKind::kVehicleCandidate: return "vehicle";
    case ObjectKind::kTooSmall: return "too small";
    case ObjectKind::kTooLarge: return "too large";
    case ObjectKind::kNotVehicleShaped: return "not vehicle-shaped";
    case ObjectKind::kUnknown: return "unknown";
  }
  return "unknown";
}

bool scene_config_valid(const SceneConfig& c) noexcept {
  SegmentParams sp;
  return required_workspace_bytes(object_config(c)) > 0 && terrain_params_valid(terrain_params(c)) &&
         gates_valid(c) && c.top_n >= 1u && c.top_n <= kMaxSceneTopN && c.max_objects >= 1u &&
         c.max_objects <= kMaxSceneObjects && c.max_tile_points >= 1u &&
         c.max_tile_points <= kMaxSceneTilePoints && c.max_terrain_cells >= 1u &&
         c.max_terrain_cells <= kMaxSceneGridCells && c.max_segment_cells >= 1u &&
         c.max_segment_cells <= kMaxSceneGridCells && c.min_object_points >= 1u && sp.cell > 0.0f;
}

size_t required_scene_workspace_bytes(const SceneConfig& config) noexcept {
  if (!scene_config_valid(config)) return 0;
  Arena counter;
  counter.alloc<SceneBuffers>(1);
  SceneBuffers scratch;
  carve(counter, config, scratch);
  counter.alloc<uint8_t>(required_workspace_bytes(object_config(config)) + kBufferAlignment);
  return counter.used() + kBufferAlignment;
}

Status SceneRecognizer::init(const Database* db, const SceneConfig& config, void* workspace,
                             size_t workspace_bytes) noexcept {
  buffers_ = nullptr;
  db_ = nullptr;
  if (db == nullptr || !db->is_open() || workspace == nullptr || !scene_config_valid(config))
    return Status::kInvalidArgument;
  if (reinterpret_cast<uintptr_t>(workspace) % kBufferAlignment != 0) return Status::kMisalignedBuffer;
  Arena arena(workspace, workspace_bytes);
  SceneBuffers* b = arena.alloc<SceneBuffers>(1);
  if (b == nullptr) return Status::kWorkspaceTooSmall;
  new (b) SceneBuffers();
  Status s = carve(arena, config, *b);
  if (s != Status::kOk) return s;
  const RecognizerConfig rc = object_config(config);
  const size_t rec_bytes = required_workspace_bytes(rc);
  uint8_t* raw = arena.alloc<uint8_t>(rec_bytes + kBufferAlignment);
  if (raw == nullptr) return Status::kWorkspaceTooSmall;
  const uintptr_t aligned =
      (reinterpret_cast<uintptr_t>(raw) + kBufferAlignment - 1u) / kBufferAlignment * kBufferAlignment;
  s = b->recognizer.init(db, rc, reinterpret_cast<void*>(aligned), rec_bytes);
  if (s != Status::kOk) return s;
  db_ = db;
  config_ = config;
  used_bytes_ = arena.used();
  buffers_ = b;
  return Status::kOk;
}

SceneResult SceneRecognizer::recognize(const double* xyz, uint32_t n) noexcept {
  SceneResult res;
  if (buffers_ == nullptr) return res;  // kNotOpen
  if (n > 0 && xyz == nullptr) {
    res.status = Status::kInvalidArgument;
    return res;
  }
  SceneBuffers& b = *buffers_;
  const SceneConfig& c = config_;
  res.stats.points_in = n;
  res.stats.workspace_used = used_bytes_;
  if (n > c.max_tile_points) {
    res.status = Status::kTooManyPoints;  // refused whole: never truncated
    return res;
  }
  // Origin: the finite points' minimum corner; local floats keep ~1e-5 m over 100 m.
  constexpr double kFar = std::numeric_limits<double>::infinity();
  double origin[3] = {kFar, kFar, kFar};
  uint32_t m = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const double* p = xyz + 3u * i;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
    for (int a = 0; a < 3; ++a) origin[a] = p[a] < origin[a] ? p[a] : origin[a];
    ++m;
  }
  res.stats.points_nonfinite = n - m;
  if (m == 0) {
    res.status = Status::kEmptyCloud;
    return res;
  }
  m = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const double* p = xyz + 3u * i;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
    for (int a = 0; a < 3; ++a) b.local[3u * m + a] = static_cast<float>(p[a] - origin[a]);
    ++m;
  }
  TerrainStats ts;
  res.status = classify_terrain(b.local, m, terrain_params(c), b.terrain, b.height, b.ground, &ts);
  if (res.status != Status::kOk) return res;
  res.stats.points_ground = ts.points_ground;
  res.stats.terrain_cells = ts.cells;
  res.stats.terrain_windows = ts.windows;
  SegmentParams sp;
  sp.cell = c.segment_cell;
  sp.split_height = c.layer_split_height;
  sp.min_points = c.min_object_points;
  sp.max_objects = c.max_objects;
  SegmentStats ss;
  const Status seg = segment_objects(b.local, b.height, b.ground, m, sp, b.segments, b.shapes, b.label, &ss);
  if (seg != Status::kOk && seg != Status::kTooManyObjects) {
    res.status = seg;
    return res;
  }
  res.stats.segment_cells = ss.cells;
  res.stats.components = ss.components;
  res.stats.objects_dropped = ss.dropped;
  res.stats.points_in_objects = ss.points_in_objects;
  res.stats.points_fragments = ss.points_fragments;
  // Counting sort of the object points: each object's points contiguous.
  for (uint32_t k = 0; k <= ss.objects; ++k) b.offsets[k] = 0;
  for (uint32_t i = 0; i < m; ++i)
    if (b.label[i] != kNoObject) ++b.offsets[b.label[i] + 1u];
  for (uint32_t k = 0; k < ss.objects; ++k) b.offsets[k + 1u] += b.offsets[k];
  for (uint32_t i = 0; i < m; ++i) {
    if (b.label[i] == kNoObject) continue;
    const uint32_t at = b.offsets[b.label[i]]++;
    for (int a = 0; a < 3; ++a) b.gathered[3u * at + a] = b.local[3u * i + a];
  }
  for (uint32_t k = ss.objects; k > 0; --k) b.offsets[k] = b.offsets[k - 1u];  // back to starts
  b.offsets[0] = 0;
  for (uint32_t k = 0; k < ss.objects; ++k) {
    const ObjectShape& o = b.shapes[k];
    SceneObject& out = b.objects[k];
    out = SceneObject{};
    out.points = o.points;
    out.center[0] = origin[0] + static_cast<double>(o.cx);
    out.center[1] = origin[1] + static_cast<double>(o.cy);
    out.center[2] = origin[2] + 0.5 * static_cast<double>(o.zmin + o.zmax);
    out.extent[0] = o.length();
    out.extent[1] = o.width();
    out.extent[2] = o.hmax;
    out.heading_deg = std::atan2(o.ay, o.ax) * (180.0f / 3.14159265f);
    out.min_height = o.hmin;
    out.high_layer = o.high_layer;
    out.kind = classify(o, c);
    if (out.kind == ObjectKind::kVehicleCandidate) {
      const Result r = b.recognizer.recognize(b.gathered + 3u * static_cast<size_t>(b.offsets[k]), o.points);
      out.status = r.status;
      out.stats = r.stats;
      res.stats.recognition_hypotheses += r.stats.hypotheses;
      res.stats.recognition_candidates += r.stats.candidates;
      if (r.status != Status::kOk || r.ranking_count == 0) {
        out.kind = ObjectKind::kUnknown;
      } else {
        const blob::ModelRecord& best = db_->model(r.ranking[0].model);
        out.ground_gap = r.ranking[0].has_pose ? ground_gap(r.ranking[0].pose, best, b.terrain)
                                               : std::numeric_limits<float>::quiet_NaN();
        RankedModel* dst = b.rankings + static_cast<size_t>(k) * c.top_n;
        out.ranking_count = r.ranking_count < c.top_n ? r.ranking_count : c.top_n;
        for (uint32_t j = 0; j < out.ranking_count; ++j) {
          dst[j] = r.ranking[j];
          for (int a = 0; a < 3; ++a) dst[j].pose.translation[a] += origin[a];  // local -> georeferenced
        }
        out.ranking = dst;
        out.confident = r.confident && size_agrees(o, best, c.max_size_mismatch) &&
                        not_sunk(out.ground_gap, c.max_ground_sink);
        out.group_size = r.group_size;
      }
    }
    ++res.stats.objects_by_kind[static_cast<uint32_t>(out.kind)];
  }
  res.objects = b.objects;
  res.object_count = ss.objects;
  res.status = seg;
  return res;
}

}  // namespace spinhash
