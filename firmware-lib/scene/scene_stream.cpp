// SceneStream: points pushed in along-track order (lag bounded by max_lag)
// into a fixed buffer; each row of windows runs once no point can still
// arrive in its seen rectangles: the row's terrain cells are summed
// (terrain_cells.hpp), then its windows run through the stages the tile API
// shares (scene_window.hpp), and the buffer forgets the points later rows
// do not gather (their terrain is in the cells).
#include "spinhash/scene_stream.hpp"

#include <cmath>
#include <new>

#include "scene/point_ring.hpp"
#include "scene/scene_status.hpp"
#include "scene/scene_window.hpp"
#include "scene/terrain_cells.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/scene_fields.h"
#include "util/saturating_add.hpp"

namespace spinhash {

struct StreamBuffers {
  const Database* db = nullptr;
  StreamConfig config;
  // The config's order and swath bounds, in the frame's double precision.
  double max_lag = 0, max_jump = 0, max_z = 0, swath_min = 0, swath_max = 0;
  StreamFrame frame;
  WindowLattice lattice;
  WindowBuffers window;
  PointRing ring;
  TerrainCells cells;
  double pending[3u * kMaxJumpConfirmPoints] = {};  // a jump awaiting confirmation (frame coordinates)
  uint32_t pending_count = 0;
  double gather_min_s = kUnbounded;      // the least s of the buffered points a window gathers (across)
  double rows_wait_below = -kUnbounded;  // furthest_along below this completes no row (rows_wait_below())
  bool origin_set = false;
  bool flushed = false;
  int64_t next_row = 0;  // the first row of windows not yet run
  StreamStats stats;
  SceneObjectSink sink = nullptr;
  void* sink_context = nullptr;
};

namespace {

const StreamStats kNoStreamStats{};  // stats() before init

Status carve(Arena& arena, const StreamConfig& c, StreamBuffers& b) {
  b.window.carve(arena, c.scene);
  b.ring.carve(arena, c.max_buffered_points);
  b.cells.low_band = c.scene.terrain_low_band;
  b.cells.noise_gap = c.scene.terrain_noise_gap;
  const double margin = static_cast<double>(c.scene.window_margin);
  b.cells.carve(arena, static_cast<double>(c.scene.terrain_cell),
                static_cast<double>(c.scene.window_core) + 2.0 * margin,
                static_cast<double>(c.own_max) - static_cast<double>(c.own_min) + 2.0 * margin);
  return arena.overflowed() ? Status::kWorkspaceTooSmall : Status::kOk;
}

// The along-track start of the points rows from `row` on still gather.
double needed_from(const StreamBuffers& b, int64_t row) {
  return static_cast<double>(row) * b.lattice.core - b.lattice.object_margin;
}

// Before this along track a point comes too late: its terrain cell is
// summed (or no window gathers it).
double late_before(const StreamBuffers& b) {
  const double gathered = needed_from(b, b.next_row);
  return b.cells.started && b.cells.summed_edge() > gathered ? b.cells.summed_edge() : gathered;
}

// Whether a window of the owned band gathers points at t across.
bool in_gathered_band(const StreamBuffers& b, double t) {
  return t >= b.lattice.own_min - b.lattice.object_margin && t < b.lattice.own_max + b.lattice.object_margin;
}

// Keeps the points that a later row gathers, and those whose terrain cell
// is not summed yet and that a later row's terrain sees; notes the least s
// a later row gathers.
void forget_done(StreamBuffers& b) {
  const double gathered = needed_from(b, b.next_row), summed = b.cells.summed_edge();
  const double seen = static_cast<double>(b.next_row) * b.lattice.core - b.lattice.margin;
  // The same tests on the steps (first_step_from): in_gathered_band, and
  // the along-track bounds.
  const int64_t band_lo = first_step_from(b.lattice.own_min - b.lattice.object_margin),
                band_hi = first_step_from(b.lattice.own_max + b.lattice.object_margin);
  const int64_t gathered_k = first_step_from(gathered), summed_k = first_step_from(summed),
                seen_k = first_step_from(seen);
  int64_t least = INT64_MAX;
  b.ring.keep_if_steps([&](const int32_t* k) {
    const bool in_band = k[1] >= band_lo && k[1] < band_hi;
    const bool keep = (in_band && k[0] >= gathered_k) || (k[0] >= summed_k && k[0] >= seen_k);
    if (keep && in_band && k[0] < least) least = k[0];
    return keep;
  });
  b.gather_min_s = least == INT64_MAX ? kUnbounded : from_steps(static_cast<int32_t>(least));
}

// The first row whose windows gather points at s along: row k gathers
// [k core - object_margin, (k + 1) core + object_margin).
int64_t first_row_gathering(const WindowLattice& l, double s) {
  return l.row_of(s - l.object_margin - l.core) + 1;
}

// A window of the strip whose points or terrain did not fit: counted, lost.
Status overflowed(StreamBuffers& b, uint32_t points) {
  ++b.stats.windows_overflowed;
  b.stats.scene.windows_overflowed = saturating_add(b.stats.scene.windows_overflowed, 1u);
  b.stats.points_in_overflowed += points;
  return Status::kWindowOverflow;
}

// Runs the windows [j0, j1) of row k, a strip sharing one terrain grid.
Status run_strip(StreamBuffers& b, int64_t k, uint32_t j0, uint32_t j1) {
  const WindowOutput out{b.sink, b.sink_context, &b.stats.scene, &b.stats.objects_reported,
                         &b.stats.objects_not_owned};
  const FrameRect strip = strip_rect(b.lattice, k, j0, j1);
  const Status terrain =
      build_strip_terrain(b.config.scene, b.cells, strip, strip_gather_rect(b.lattice, k, j0, j1), strip.s0,
                          strip.t0, b.window, &b.stats.scene);
  if (terrain == Status::kEmptyCloud) return Status::kOk;  // nothing to see here
  Status status = Status::kOk;
  for (uint32_t j = j0; j < j1; ++j) {
    WindowJob job;
    job.row = k;
    job.col = j;
    job.core = b.lattice.owned_area(k, j);
    job.s0 = strip.s0;  // the strip's local frame, in which its terrain lies
    job.t0 = strip.t0;
    uint32_t missed = 0;
    const uint32_t got = gather_window(b.ring, b.lattice.gather_rect(k, j), job, b.window, &missed);
    if (got == 0) continue;
    ++b.stats.windows;
    b.stats.scene.windows = saturating_add(b.stats.scene.windows, 1u);
    Status s = missed > 0 || terrain != Status::kOk
                   ? Status::kWindowOverflow
                   : run_window(*b.db, b.config.scene, b.frame, b.ring, job, got, b.window, out);
    if (s == Status::kTileTooLarge || s == Status::kWindowOverflow) s = overflowed(b, got + missed);
    status = worse_scene_status(status, s);
  }
  return status;
}

// Sums row k's terrain cells, then runs its windows over the buffer, strip
// by strip. Out of line: scripts/instructions-per-point.sh splits the
// stream's work at it.
__attribute__((noinline)) Status run_row(StreamBuffers& b, int64_t k) {
  const double core = b.lattice.core, margin = b.lattice.margin;
  b.cells.sum(b.ring, static_cast<double>(k) * core - margin, static_cast<double>(k + 1) * core + margin);
  Status status = Status::kOk;
  const uint32_t cols = b.lattice.columns(), per_strip = strip_columns(b.config.scene);
  for (uint32_t j0 = 0; j0 < cols; j0 += per_strip)
    status = worse_scene_status(status, run_strip(b, k, j0, j0 + per_strip < cols ? j0 + per_strip : cols));
  return status;
}

// The rows before this one are complete: no point within max_lag can
// still reach their seen rectangles.
int64_t complete_before(const StreamBuffers& b, double settled) {
  return b.lattice.row_of(settled - b.lattice.margin);
}

// Runs row next_row when a buffered point lies in its gather, else skips to
// the first row that gathers one (at most to `end`): the work follows the
// points, whatever the area between them.
Status run_or_skip(StreamBuffers& b, int64_t end) {
  const int64_t first = b.gather_min_s < kUnbounded ? first_row_gathering(b.lattice, b.gather_min_s) : end;
  Status status = Status::kOk;
  if (first > b.next_row) {
    b.next_row = first < end ? first : end;
  } else {
    status = run_row(b, b.next_row);
    ++b.next_row;
  }
  forget_done(b);
  b.stats.done_until = static_cast<double>(b.next_row) * b.lattice.core;
  return status;
}

// A bound below which furthest_along completes no row past next_row: row
// next_row ends where complete_before reaches next_row + 1, at
// (next_row + 1) core + margin + max_lag; the bound stays a billionth of
// that below it, far more than the rounding of complete_before's
// arithmetic, so a push below it may skip the division (the answer is
// the same: no row to run).
double rows_wait_below(const StreamBuffers& b) {
  const double edge = static_cast<double>(b.next_row + 1) * b.lattice.core + b.lattice.margin + b.max_lag;
  return edge - 1e-9 * (1.0 + std::fabs(edge));
}

// Runs every row that no point within max_lag can still reach.
Status run_complete_rows(StreamBuffers& b) {
  Status status = Status::kOk;
  const int64_t end = complete_before(b, b.stats.furthest_along - b.max_lag);
  while (b.next_row < end) status = worse_scene_status(status, run_or_skip(b, end));
  b.rows_wait_below = rows_wait_below(b);
  return status;
}

// Stores one accepted point (frame coordinates), running rows it completes.
Status take(StreamBuffers& b, const double* stz) {
  Status status = Status::kOk;
  if (stz[0] > b.stats.furthest_along) {
    b.stats.furthest_along = stz[0];
    if (stz[0] >= b.rows_wait_below) status = run_complete_rows(b);
  }
  if (!b.ring.push(stz)) {
    ++b.stats.points_overflow;
    return Status::kWindowOverflow;
  }
  if (in_gathered_band(b, stz[1]) && stz[0] < b.gather_min_s) b.gather_min_s = stz[0];
  return status;
}

void start_line(StreamBuffers& b, const double* first) {
  const StreamConfig& c = b.config;
  for (int a = 0; a < 3; ++a) b.frame.origin[a] = c.origin_given ? c.origin[a] : first[a];
  b.origin_set = true;
  double stz[3];
  b.frame.to_frame(first, stz);
  b.stats.furthest_along = stz[0];
  b.next_row = b.lattice.row_of(stz[0] - b.max_lag);
  b.stats.done_until = static_cast<double>(b.next_row) * b.lattice.core;
  b.rows_wait_below = -kUnbounded;  // the first take checks
}

// A point far ahead of the line: held until jump_confirm_points agree (a gap
// in the data), dropped as a glitch when the line goes on where it was.
Status hold_jump(StreamBuffers& b, const double* stz) {
  if (b.pending_count > 0 && std::fabs(stz[0] - b.pending[0]) > b.max_jump) {
    b.stats.points_glitch += b.pending_count;  // the held ones disagree with this one
    b.pending_count = 0;
  }
  for (int a = 0; a < 3; ++a) b.pending[3u * b.pending_count + a] = stz[a];
  if (++b.pending_count < b.config.jump_confirm_points) return Status::kOk;
  Status status = Status::kOk;
  for (uint32_t i = 0; i < b.pending_count; ++i)
    status = worse_scene_status(status, take(b, b.pending + 3u * i));
  b.pending_count = 0;
  return status;
}

Status push_one(StreamBuffers& b, const double* xyz) {
  if (!finite_xyz(xyz)) {
    ++b.stats.scene.points_nonfinite;
    return Status::kOk;
  }
  if (!b.origin_set) start_line(b, xyz);
  double stz[3];
  b.frame.to_frame(xyz, stz);
  if (std::fabs(stz[2]) > b.max_z || stz[1] < b.swath_min || stz[1] >= b.swath_max || !within_lattice(stz)) {
    ++b.stats.points_outside;
    return Status::kOk;
  }
  if (stz[0] < late_before(b)) {
    ++b.stats.points_late;  // beyond the declared lag: its terrain is made, or its windows have run
    return Status::kPointsLate;
  }
  if (stz[0] > b.stats.furthest_along + b.max_jump) return hold_jump(b, stz);
  if (b.pending_count > 0) {
    b.stats.points_glitch += b.pending_count;
    b.pending_count = 0;
  }
  return take(b, stz);
}

}  // namespace

size_t required_stream_workspace_bytes(const StreamConfig& config) noexcept {
  if (!stream_config_valid(config)) return 0;
  Arena counter;
  counter.alloc<StreamBuffers>(1);
  StreamBuffers scratch;
  carve(counter, config, scratch);
  return counter.used() + kBufferAlignment;
}

Status SceneStream::init(const Database* db, const StreamConfig& config, void* workspace,
                         size_t workspace_bytes, SceneObjectSink sink, void* sink_context) noexcept {
  buffers_ = nullptr;
  if (db == nullptr || !db->is_open() || workspace == nullptr || !stream_config_valid(config))
    return Status::kInvalidArgument;
  if (reinterpret_cast<uintptr_t>(workspace) % kBufferAlignment != 0) return Status::kMisalignedBuffer;
  Arena arena(workspace, workspace_bytes);
  StreamBuffers* b = arena.alloc<StreamBuffers>(1);
  if (b == nullptr) return Status::kWorkspaceTooSmall;
  new (b) StreamBuffers();
  Status s = carve(arena, config, *b);
  if (s != Status::kOk) return s;
  s = b->window.init_recognizer(db, config.scene);
  if (s != Status::kOk) return s;
  b->db = db;
  b->config = config;
  b->max_lag = static_cast<double>(config.max_lag);
  b->max_jump = static_cast<double>(config.max_jump);
  b->max_z = static_cast<double>(config.max_z_offset);
  b->swath_min = static_cast<double>(config.swath_min);
  b->swath_max = static_cast<double>(config.swath_max);
  b->frame.set_heading(static_cast<double>(config.heading_deg));
  b->lattice.core = static_cast<double>(config.scene.window_core);
  b->lattice.margin = static_cast<double>(config.scene.window_margin);
  b->lattice.object_margin = static_cast<double>(config.scene.object_margin);
  b->lattice.own_min = static_cast<double>(config.own_min);
  b->lattice.own_max = static_cast<double>(config.own_max);
  b->cells.start(b->lattice.own_min - b->lattice.margin);
  b->sink = sink;
  b->sink_context = sink_context;
  b->stats.scene.workspace_used = arena.used();
  used_bytes_ = arena.used();
  buffers_ = b;
  return Status::kOk;
}

Status SceneStream::push(const double* xyz, uint32_t n) noexcept {
  if (buffers_ == nullptr) return Status::kNotOpen;
  if (n > 0 && xyz == nullptr) return Status::kInvalidArgument;
  StreamBuffers& b = *buffers_;
  if (b.flushed) {
    b.stats.points_after_flush += n;
    return Status::kStreamFlushed;
  }
  Status status = Status::kOk;
  for (uint32_t i = 0; i < n; ++i)
    status = worse_scene_status(status, push_one(b, xyz + 3u * static_cast<size_t>(i)));
  b.stats.points_pushed += n;
  return status;
}

Status SceneStream::flush() noexcept {
  if (buffers_ == nullptr) return Status::kNotOpen;
  StreamBuffers& b = *buffers_;
  if (b.flushed) return Status::kOk;
  b.flushed = true;
  b.stats.points_glitch += b.pending_count;  // never confirmed
  b.pending_count = 0;
  if (!b.origin_set) return Status::kOk;  // nothing was pushed
  Status status = Status::kOk;
  const int64_t end = b.lattice.row_of(b.stats.furthest_along) + 1;  // later cores hold no point
  while (b.next_row < end) status = worse_scene_status(status, run_or_skip(b, end));
  b.ring.count = 0;
  b.gather_min_s = kUnbounded;
  b.stats.done_until = static_cast<double>(b.next_row) * b.lattice.core;
  return status;
}

void SceneStream::reset(const double* origin) noexcept {
  if (buffers_ == nullptr) return;
  StreamBuffers& b = *buffers_;
  b.ring.count = 0;
  b.cells.start(b.lattice.own_min - b.lattice.margin);
  b.pending_count = 0;
  b.gather_min_s = kUnbounded;
  b.origin_set = false;
  if (origin != nullptr && finite_xyz(origin)) {
    b.config.origin_given = true;
    for (int a = 0; a < 3; ++a) b.config.origin[a] = origin[a];
  }
  b.flushed = false;
  b.next_row = 0;
  const size_t used = b.stats.scene.workspace_used;
  b.stats = StreamStats{};
  b.stats.scene.workspace_used = used;
}

namespace {

// Adding one line's counts to another's, field by field from the one list
// (scene_fields.h): counts add (32-bit ones saturate), positions along the
// line take the furthest, the workspace is the largest.
void add_field_U32(uint32_t& into, uint32_t b) { into = saturating_add(into, b); }
void add_field_U64(uint64_t& into, uint64_t b) { into += b; }
void add_field_F64(double& into, double b) { into = b > into ? b : into; }
void add_field_SIZE(size_t& into, size_t b) { into = b > into ? b : into; }
void add_field_KINDS(uint32_t (&into)[kObjectKinds], const uint32_t (&b)[kObjectKinds]) {
  for (uint32_t k = 0; k < kObjectKinds; ++k) into[k] = saturating_add(into[k], b[k]);
}
void add_field_SCENE(SceneStats& into, const SceneStats& b) {
#define SPINHASH_ADD(kind, name, json) add_field_##kind(into.name, b.name);
  SPINHASH_SCENE_STATS_FIELDS(SPINHASH_ADD)
#undef SPINHASH_ADD
}

}  // namespace

void add_stream_stats(StreamStats& into, const StreamStats& line) noexcept {
#define SPINHASH_ADD(kind, name, json) add_field_##kind(into.name, line.name);
  SPINHASH_STREAM_STATS_FIELDS(SPINHASH_ADD)
#undef SPINHASH_ADD
}

const StreamStats& SceneStream::stats() const noexcept {
  return buffers_ == nullptr ? kNoStreamStats : buffers_->stats;
}

}  // namespace spinhash
