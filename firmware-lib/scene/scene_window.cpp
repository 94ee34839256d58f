// One window: terrain -> objects -> size gates -> ownership -> Recognizer
// per owned vehicle candidate -> the sink.
#include "scene/scene_window.hpp"

#include <cmath>
#include <limits>
#include <new>

#include "recognize/level_evidence.hpp"
#include "spinhash/answered.hpp"
#include "spinhash/limits.hpp"
#include "util/angle_math.hpp"
#include "util/heap_sort.hpp"
#include "util/saturating_add.hpp"

namespace spinhash {
namespace {

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

// The model's box bottom above the terrain under `pose` (world-aligned,
// from the object's origin, which lies at (ds, dt) in the window's grid
// frame), m: the mean over its four bottom corners that have terrain under
// them; NaN when none has. The terrain grid lies in the frame's axes.
float ground_gap(const Pose& pose, const blob::ModelRecord& m, const TerrainParts& terrain,
                 const StreamFrame& frame, float ds, float dt) {
  const float ax = static_cast<float>(frame.ax), ay = static_cast<float>(frame.ay);
  float sum = 0.0f;
  uint32_t corners = 0;
  for (int i = 0; i < 4; ++i) {
    const float c[3] = {i & 1 ? m.bbox_max[0] : m.bbox_min[0], i & 2 ? m.bbox_max[1] : m.bbox_min[1],
                        m.bbox_min[2]};
    float x[3];
    for (int r = 0; r < 3; ++r)
      x[r] = pose.rotation[3 * r] * c[0] + pose.rotation[3 * r + 1] * c[1] + pose.rotation[3 * r + 2] * c[2] +
             static_cast<float>(pose.translation[r]);
    const float ground = terrain_height_at(terrain, x[0] * ax + x[1] * ay + ds, -x[0] * ay + x[1] * ax + dt);
    if (!std::isfinite(ground)) continue;
    sum += x[2] - ground;
    ++corners;
  }
  return corners > 0 ? sum / static_cast<float>(corners) : std::numeric_limits<float>::quiet_NaN();
}

// Not sunk deeper than `tolerance`; NaN (no terrain to test against) passes.
bool not_sunk(float gap, float tolerance) { return !(gap < -tolerance); }

// Exact footprint boxes in the stream frame, from the points' sources:
// the same for every window that sees the same points.
void object_boxes(const PointRing& ring, uint32_t n, uint32_t objects, WindowBuffers& b) {
  for (uint32_t k = 0; k < objects; ++k) {
    double* box = b.box + 4u * k;
    box[0] = box[2] = kUnbounded;
    box[1] = box[3] = -kUnbounded;
  }
  for (uint32_t i = 0; i < n; ++i) {
    if (b.label[i] == kNoObject) continue;
    double stz[3];
    ring.get(b.source[i], stz);
    double* box = b.box + 4u * b.label[i];
    box[0] = stz[0] < box[0] ? stz[0] : box[0];
    box[1] = stz[0] > box[1] ? stz[0] : box[1];
    box[2] = stz[1] < box[2] ? stz[1] : box[2];
    box[3] = stz[1] > box[3] ? stz[1] : box[3];
  }
}

// The frame offset of object k's own origin: its box's min corner on a 1 m
// lattice. Its points go to the recognizer relative to it, from their exact
// coordinates, so every window and the tile API hand it the same floats.
void object_origin(const WindowBuffers& b, uint32_t k, double* s0, double* t0) {
  *s0 = std::floor(b.box[4u * k]);
  *t0 = std::floor(b.box[4u * k + 2u]);
}

// Counting sort of the object points into b.gathered, world-aligned, each
// object relative to its own origin; b.offsets[k] = object k's first point.
void gather_objects(const PointRing& ring, uint32_t n, uint32_t objects, const StreamFrame& frame,
                    WindowBuffers& b) {
  for (uint32_t k = 0; k <= objects; ++k) b.offsets[k] = 0;
  for (uint32_t i = 0; i < n; ++i)
    if (b.label[i] != kNoObject) ++b.offsets[b.label[i] + 1u];
  for (uint32_t k = 0; k < objects; ++k) b.offsets[k + 1u] += b.offsets[k];
  for (uint32_t i = 0; i < n; ++i) {
    if (b.label[i] == kNoObject) continue;
    const uint32_t at = b.offsets[b.label[i]]++;
    double stz[3], s0, t0, dx, dy;
    ring.get(b.source[i], stz);
    object_origin(b, b.label[i], &s0, &t0);
    frame.offset_to_world(stz[0] - s0, stz[1] - t0, &dx, &dy);
    float* q = b.gathered + 3u * static_cast<size_t>(at);
    q[0] = static_cast<float>(dx);
    q[1] = static_cast<float>(dy);
    q[2] = static_cast<float>(stz[2]);
  }
  for (uint32_t k = objects; k > 0; --k) b.offsets[k] = b.offsets[k - 1u];  // back to starts
  b.offsets[0] = 0;
}

// The object's description in world coordinates (no recognition yet).
SceneObject describe(const ObjectShape& o, const SceneConfig& c, const StreamFrame& frame,
                     const WindowJob& job) {
  SceneObject out;
  out.points = o.points;
  double dx, dy;
  frame.offset_to_world(job.s0 + static_cast<double>(o.cx), job.t0 + static_cast<double>(o.cy), &dx, &dy);
  out.center[0] = frame.origin[0] + dx;
  out.center[1] = frame.origin[1] + dy;
  out.center[2] = frame.origin[2] + 0.5 * static_cast<double>(o.zmin + o.zmax);
  out.extent[0] = o.length();
  out.extent[1] = o.width();
  out.extent[2] = o.hmax;
  const float frame_deg = rad_to_deg(static_cast<float>(std::atan2(frame.ay, frame.ax)));
  float heading = rad_to_deg(std::atan2(o.ay, o.ax)) + frame_deg;
  if (heading > 180.0f) heading -= 360.0f;
  if (heading <= -180.0f) heading += 360.0f;
  out.heading_deg = heading;
  out.min_height = o.hmin;
  out.high_layer = o.high_layer;
  out.kind = classify(o, c);
  return out;
}

struct Point3f {
  float v[3];
};

// The object's points in one canonical order (by x, y, z): the recognizer's
// sampling follows point order, and windows, tiles and files meet an
// object's points in different orders.
void canonical_order(float* xyz, uint32_t n) {
  heap_sort(reinterpret_cast<Point3f*>(xyz), n, [](const Point3f& a, const Point3f& b) {
    if (a.v[0] != b.v[0]) return a.v[0] < b.v[0];
    if (a.v[1] != b.v[1]) return a.v[1] < b.v[1];
    return a.v[2] < b.v[2];
  });
}

// Recognises the vehicle candidate k of the window into out (and b.ranking),
// its work capped at `work_cap` units (Recognizer::set_work_cap); returns
// the work it spent.
uint64_t recognize_object(const Database& db, const SceneConfig& c, const StreamFrame& frame,
                          const WindowJob& job, uint32_t k, uint64_t work_cap, WindowBuffers& b,
                          SceneObject& out, SceneStats* stats) {
  const ObjectShape& o = b.shapes[k];
  float* points = b.gathered + 3u * static_cast<size_t>(b.offsets[k]);
  canonical_order(points, o.points);
  // The tile's terrain measures the object's top (the class envelope's
  // height; its noise: the recognizer's sigma_surface, not measured per
  // object); the object's points start ground_height above it.
  b.recognizer.set_work_cap(work_cap);
  const Result r = b.recognizer.recognize(
      points, o.points, ObjectTerrain{o.hmax, c.recognizer.refine.sigma_surface, c.ground_height});
  out.status = r.status;
  out.stats = r.stats;
  stats->recognition_hypotheses += r.stats.draws.hypotheses;
  stats->recognition_candidates += r.stats.candidates.kept;
  stats->recognition_work += r.stats.cascade.work;
  if (!has_answer(r.status) || r.ranking_count == 0) {
    out.kind = ObjectKind::kUnknown;
    return r.stats.cascade.work;
  }
  const blob::ModelRecord& best = db.model(r.ranking[0].model);
  double s0, t0;
  object_origin(b, k, &s0, &t0);
  const float ds = static_cast<float>(s0 - job.s0), dt = static_cast<float>(t0 - job.t0);
  out.ground_gap = r.ranking[0].has_pose ? ground_gap(r.ranking[0].pose, best, b.terrain, frame, ds, dt)
                                         : std::numeric_limits<float>::quiet_NaN();
  double world[2];
  frame.offset_to_world(s0, t0, &world[0], &world[1]);
  const double shift[3] = {frame.origin[0] + world[0], frame.origin[1] + world[1], frame.origin[2]};
  out.ranking_count = r.ranking_count < c.top_n ? r.ranking_count : c.top_n;
  for (uint32_t j = 0; j < out.ranking_count; ++j) {
    b.ranking[j] = r.ranking[j];
    for (int a = 0; a < 3; ++a) b.ranking[j].pose.translation[a] += shift[a];  // local -> georeferenced
  }
  out.ranking = b.ranking;
  out.confident =
      r.confident && size_agrees(o, best, c.max_size_mismatch) && not_sunk(out.ground_gap, c.max_ground_sink);
  out.group_size = r.group_size;
  out.class_count = r.class_ranking_count;
  for (uint32_t j = 0; j < r.class_ranking_count && j < kVehicleClassCount; ++j)
    out.classes[j] = r.class_ranking[j];
  out.class_confident =
      r.class_confident && out.class_count > 0 &&
      size_agrees(o, db.model(out.classes[0].model), c.class_size_factor * c.max_size_mismatch);
  out.group_count = r.group_ranking_count;
  for (uint32_t j = 0; j < r.group_ranking_count && j < kVehicleGroupCount; ++j)
    out.groups[j] = r.group_ranking[j];
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) out.levels[l] = r.levels[l];
  out.levels[level_index(AnswerLevel::kModel)].confident = out.confident;
  out.levels[level_index(AnswerLevel::kClass)].confident = out.class_confident;
  AnswerLeaders first;
  first.model = out.ranking;
  first.vehicle_class = out.class_count > 0 ? out.classes : nullptr;
  first.group = out.group_count > 0 ? out.groups : nullptr;
  out.level = answer_level(db, out.levels, first);
  return r.stats.cascade.work;
}

}  // namespace

RecognizerConfig scene_object_config(const SceneConfig& c) {
  RecognizerConfig r = c.recognizer;
  r.ground.ground_clearance = 0.0f;  // the scene removed the ground already, on any slope
  return r;
}

TerrainParams scene_terrain_params(const SceneConfig& c) {
  TerrainParams p;
  p.cell = c.terrain_cell;
  p.max_window = c.terrain_window;
  p.slope = c.terrain_slope;
  p.dh0 = c.terrain_dh0;
  p.dh_max = c.terrain_dh_max;
  p.ground_height = c.ground_height;
  p.low_band = c.terrain_low_band;
  p.noise_gap = c.terrain_noise_gap;
  p.noise_reach = c.terrain_noise_reach;
  p.noise_support = c.terrain_noise_support;
  return p;
}

SegmentParams scene_segment_params(const SceneConfig& c) {
  SegmentParams p;
  p.cell = c.segment_cell;
  p.split_height = c.layer_split_height;
  p.min_points = c.min_object_points;
  p.max_objects = c.max_objects;
  p.column_bin = c.column_bin;
  p.layer_gap_bins = static_cast<uint32_t>(std::lround(c.layer_gap / c.column_bin));
  return p;
}

void WindowBuffers::carve(Arena& arena, const SceneConfig& c) {
  const size_t np = c.max_tile_points;
  capacity = c.max_tile_points;
  local = arena.alloc<float>(3u * np);
  source = arena.alloc<uint32_t>(np);
  height = arena.alloc<float>(np);
  ground = arena.alloc<uint8_t>(np);
  label = arena.alloc<uint32_t>(np);
  gathered = arena.alloc<float>(3u * np);
  offsets = arena.alloc<uint32_t>(c.max_objects + 1u);
  box = arena.alloc<double>(4u * static_cast<size_t>(c.max_objects));
  shapes = arena.alloc<ObjectShape>(c.max_objects);
  ranking = arena.alloc<RankedModel>(c.top_n);
  terrain.carve(arena, c.max_terrain_cells);
  segments.carve(arena, c.max_segment_cells);
  recognizer_bytes_ = required_workspace_bytes(scene_object_config(c));
  uint8_t* raw = arena.alloc<uint8_t>(recognizer_bytes_ + kBufferAlignment);
  recognizer_workspace_ = nullptr;
  if (raw != nullptr) {
    const uintptr_t at =
        (reinterpret_cast<uintptr_t>(raw) + kBufferAlignment - 1u) / kBufferAlignment * kBufferAlignment;
    recognizer_workspace_ = reinterpret_cast<void*>(at);
  }
}

Status WindowBuffers::init_recognizer(const Database* db, const SceneConfig& c) {
  if (recognizer_workspace_ == nullptr) return Status::kWorkspaceTooSmall;
  return recognizer.init(db, scene_object_config(c), recognizer_workspace_, recognizer_bytes_);
}

uint32_t strip_columns(const SceneConfig& c) {
  const double cell = static_cast<double>(c.terrain_cell), core = static_cast<double>(c.window_core);
  const double seen = core + 2.0 * static_cast<double>(c.window_margin);
  const double rows = seen / cell + 2.0;  // with the snap's extra cells, as the grid may need
  uint32_t m = 1;
  while (m < kMaxStripColumns &&
         (static_cast<double>(m + 1u) * core + 2.0 * static_cast<double>(c.window_margin)) / cell + 2.0 <=
             static_cast<double>(c.max_terrain_cells) / rows)
    ++m;
  return m;
}

FrameRect strip_rect(const WindowLattice& lattice, int64_t k, uint32_t j0, uint32_t j1) {
  FrameRect r = lattice.seen_rect(k, j0);
  r.t1 = lattice.seen_rect(k, j1 - 1u).t1;
  return r;
}

FrameRect strip_gather_rect(const WindowLattice& lattice, int64_t k, uint32_t j0, uint32_t j1) {
  FrameRect r = lattice.gather_rect(k, j0);
  r.t1 = lattice.gather_rect(k, j1 - 1u).t1;
  return r;
}

namespace {

// The filter over the strip's filled cells, counted.
Status finish_strip_terrain(const SceneConfig& c, WindowBuffers& b, SceneStats* st) {
  const uint32_t windows = terrain_finish(b.terrain, scene_terrain_params(c));
  st->terrain_cells = saturating_add(st->terrain_cells, b.terrain.cells);
  st->terrain_windows = saturating_add(st->terrain_windows, windows);
  return Status::kOk;
}

}  // namespace

uint32_t gather_window(const PointRing& ring, const FrameRect& seen, const WindowJob& job, WindowBuffers& b,
                       uint32_t* missed) {
  uint32_t got = 0;
  *missed = 0;
  const StepRect on_steps(seen);
  ring.for_blocks_meeting(on_steps.s0, on_steps.s1, [&](uint32_t i) {
    if (!on_steps.holds(ring.steps + 3u * static_cast<size_t>(i))) return;
    double stz[3];
    ring.get(i, stz);
    if (got >= b.capacity) {
      ++*missed;
      return;
    }
    float* p = b.local + 3u * static_cast<size_t>(got);
    p[0] = static_cast<float>(stz[0] - job.s0);
    p[1] = static_cast<float>(stz[1] - job.t0);
    p[2] = static_cast<float>(stz[2]);
    b.source[got++] = i;
  });
  return got;
}

Status build_strip_terrain(const SceneConfig& c, const TerrainCells& cells, const FrameRect& seen,
                           const FrameRect& gathered, double s0, double t0, WindowBuffers& b,
                           SceneStats* st) {
  const double om = static_cast<double>(c.object_margin);
  const FrameRect needed{gathered.s0 - om, gathered.s1 + om, gathered.t0 - om, gathered.t1 + om};
  const Status s = cells.fill(seen, needed, s0, t0, terrain_reach_cells(scene_terrain_params(c)), b.terrain);
  return s != Status::kOk ? s : finish_strip_terrain(c, b, st);
}

// The per-point counts of the points in the window's core: the margins
// overlap, and a point seen by several windows is counted once, by the
// window that owns it. Not ground and in no object: a fragment (or an
// object past max_objects). Ground more than noise_gap under the terrain:
// low noise (none when the test is off). Without labels (segmentation
// failed) only the points and the ground.
void count_owned_points(const PointRing& ring, const WindowJob& job, uint32_t n, const WindowBuffers& b,
                        bool labelled, float noise_gap, SceneStats& st) {
  uint32_t owned = 0, ground = 0, in_objects = 0, low_noise = 0;
  // area_holds on the steps (the core as a rectangle of the frame).
  const StepRect core(FrameRect{job.core.min[0], job.core.max[0], job.core.min[1], job.core.max[1]});
  for (uint32_t i = 0; i < n; ++i) {
    if (!core.holds(ring.steps + 3u * static_cast<size_t>(b.source[i]))) continue;
    ++owned;
    ground += b.ground[i] ? 1u : 0u;
    low_noise += noise_gap > 0.0f && b.height[i] < -noise_gap ? 1u : 0u;
    in_objects += labelled && b.label[i] != kNoObject ? 1u : 0u;
  }
  st.points_in = saturating_add(st.points_in, owned);
  st.points_ground = saturating_add(st.points_ground, ground);
  st.points_low_noise = saturating_add(st.points_low_noise, low_noise);
  if (!labelled) return;
  st.points_in_objects = saturating_add(st.points_in_objects, in_objects);
  st.points_fragments = saturating_add(st.points_fragments, owned - ground - in_objects);
}

Status run_window(const Database& db, const SceneConfig& c, const StreamFrame& frame, const PointRing& ring,
                  const WindowJob& job, uint32_t n, WindowBuffers& b, const WindowOutput& out) {
  SceneStats& st = *out.scene;
  if (n == 0) return Status::kOk;
  terrain_heights(b.terrain, b.local, n, c.ground_height, b.height, b.ground);
  const SegmentParams sp = scene_segment_params(c);
  SegmentStats ss;
  const Status seg = segment_objects(b.local, b.height, b.ground, n, sp, b.segments, b.shapes, b.label, &ss);
  const bool labelled = seg == Status::kOk || seg == Status::kTooManyObjects;
  count_owned_points(ring, job, n, b, labelled, c.terrain_noise_gap, st);
  if (!labelled) return seg;
  st.segment_cells = saturating_add(st.segment_cells, ss.cells);
  st.components = saturating_add(st.components, ss.components);
  st.objects_dropped = saturating_add(st.objects_dropped, ss.dropped);
  object_boxes(ring, n, ss.objects, b);
  gather_objects(ring, n, ss.objects, frame, b);
  // The window's work budget, shared in the order of its objects (none when
  // window_max_work is 0): a query may pass its cap by one feature's scan,
  // one pair or pose, or one step of the refine stage
  // (recognize/work_meter.hpp), so what is left never goes below 0.
  uint64_t work_left = c.window_max_work > 0u ? c.window_max_work : Recognizer::kNoWorkCap;
  for (uint32_t k = 0; k < ss.objects; ++k) {
    const double* box = b.box + 4u * k;
    if (!area_holds(job.core, 0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]))) {
      ++*out.objects_not_owned;  // another window reports it
      continue;
    }
    SceneObject o = describe(b.shapes[k], c, frame, job);
    if (o.kind == ObjectKind::kVehicleCandidate && work_left == 0u) {
      o.kind = ObjectKind::kUnknown;  // the window's work is spent: not recognised
      o.status = Status::kWorkCapReached;
      st.objects_out_of_work = saturating_add(st.objects_out_of_work, 1u);
    } else if (o.kind == ObjectKind::kVehicleCandidate) {
      const uint64_t spent = recognize_object(db, c, frame, job, k, work_left, b, o, &st);
      work_left = spent < work_left ? work_left - spent : 0u;
    }
    st.objects_by_kind[static_cast<uint32_t>(o.kind)] =
        saturating_add(st.objects_by_kind[static_cast<uint32_t>(o.kind)], 1u);
    ++*out.objects_reported;
    if (out.sink != nullptr) out.sink(out.context, o, job.row, job.col);
  }
  return seg;
}

}  // namespace spinhash
