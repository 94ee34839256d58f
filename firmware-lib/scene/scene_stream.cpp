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
#include "scene/scene_window.hpp"
#include "scene/terrain_cells.hpp"
#include "spinhash/limits.hpp"

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
  double pending[3u * kJumpConfirmPoints] = {};  // a jump awaiting confirmation (frame coordinates)
  uint32_t pending_count = 0;
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

// Keeps the points a later row gathers, and those whose terrain cell is
// not summed yet (points across beyond the gathered band count only there).
void forget_done(StreamBuffers& b) {
  const double s_keep = needed_from(b, b.next_row), summed = b.cells.summed_edge();
  const double t_lo = b.lattice.own_min - b.lattice.object_margin,
               t_hi = b.lattice.own_max + b.lattice.object_margin;
  b.ring.keep_if(
      [&](const double* p) { return p[0] >= s_keep && ((p[1] >= t_lo && p[1] < t_hi) || p[0] >= summed); });
}

// Keeps the worse of two outcomes: a lost window outranks a full list.
Status worse(Status a, Status b) {
  if (a == Status::kWindowOverflow || b == Status::kWindowOverflow) return Status::kWindowOverflow;
  return a != Status::kOk ? a : b;
}

// A window of the strip whose points or terrain did not fit: counted, lost.
Status overflowed(StreamBuffers& b, uint32_t points) {
  ++b.stats.windows_overflowed;
  b.stats.points_in_overflowed += points;
  return Status::kWindowOverflow;
}

// Runs the windows [j0, j1) of row k, a strip sharing one terrain grid.
Status run_strip(StreamBuffers& b, int64_t k, uint32_t j0, uint32_t j1) {
  const WindowSource src{nullptr, &b.ring, &b.frame};
  const WindowOutput out{b.sink, b.sink_context, &b.stats.scene, &b.stats.objects_reported,
                         &b.stats.objects_not_owned};
  const FrameRect strip = strip_rect(b.lattice, k, j0, j1);
  const Status terrain =
      build_strip_terrain(b.config.scene, b.cells, strip, strip.s0, strip.t0, b.window, &b.stats.scene);
  if (terrain == Status::kEmptyCloud) return Status::kOk;  // nothing to see here
  Status status = Status::kOk;
  for (uint32_t j = j0; j < j1; ++j) {
    WindowJob job;
    job.row = k;
    job.col = j;
    job.core = b.lattice.core_rect(k, j);
    job.s0 = strip.s0;  // the strip's local frame, in which its terrain lies
    job.t0 = strip.t0;
    uint32_t missed = 0;
    const uint32_t got =
        gather_window(src, b.ring.count, b.lattice.gather_rect(k, j), job, b.window, &missed);
    if (got == 0) continue;
    ++b.stats.windows;
    Status s = missed > 0 || terrain != Status::kOk
                   ? Status::kWindowOverflow
                   : run_window(*b.db, b.config.scene, b.frame, src, job, got, b.window, out);
    if (s == Status::kTileTooLarge || s == Status::kWindowOverflow) s = overflowed(b, got + missed);
    status = worse(status, s);
  }
  return status;
}

// Sums row k's terrain cells, then runs its windows over the buffer, strip
// by strip.
Status run_row(StreamBuffers& b, int64_t k) {
  const double core = b.lattice.core, margin = b.lattice.margin;
  b.cells.sum(b.ring, static_cast<double>(k) * core - margin, static_cast<double>(k + 1) * core + margin);
  Status status = Status::kOk;
  const uint32_t cols = b.lattice.columns(), per_strip = strip_columns(b.config.scene);
  for (uint32_t j0 = 0; j0 < cols; j0 += per_strip)
    status = worse(status, run_strip(b, k, j0, j0 + per_strip < cols ? j0 + per_strip : cols));
  return status;
}

// Runs every row that no point within max_lag can still reach.
Status run_complete_rows(StreamBuffers& b) {
  Status status = Status::kOk;
  const double settled = b.stats.furthest_along - b.max_lag;
  while (settled >= static_cast<double>(b.next_row + 1) * b.lattice.core + b.lattice.margin) {
    if (b.ring.count == 0) {  // nothing buffered (a confirmed gap): skip the empty rows at once
      b.next_row = b.lattice.row_of(settled - b.lattice.margin);
      b.stats.done_until = static_cast<double>(b.next_row) * b.lattice.core;
      break;
    }
    status = worse(status, run_row(b, b.next_row));
    ++b.next_row;
    forget_done(b);
    b.stats.done_until = static_cast<double>(b.next_row) * b.lattice.core;
  }
  return status;
}

// Stores one accepted point (frame coordinates), running rows it completes.
Status take(StreamBuffers& b, const double* stz) {
  Status status = Status::kOk;
  if (stz[0] > b.stats.furthest_along) {
    b.stats.furthest_along = stz[0];
    status = run_complete_rows(b);
  }
  if (!b.ring.push(stz)) {
    ++b.stats.points_overflow;
    status = Status::kWindowOverflow;
  }
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
}

// A point far ahead of the line: held until kJumpConfirmPoints agree (a gap
// in the data), dropped as a glitch when the line goes on where it was.
Status hold_jump(StreamBuffers& b, const double* stz) {
  if (b.pending_count > 0 && std::fabs(stz[0] - b.pending[0]) > b.max_jump) {
    b.stats.points_glitch += b.pending_count;  // the held ones disagree with this one
    b.pending_count = 0;
  }
  for (int a = 0; a < 3; ++a) b.pending[3u * b.pending_count + a] = stz[a];
  if (++b.pending_count < kJumpConfirmPoints) return Status::kOk;
  Status status = Status::kOk;
  for (uint32_t i = 0; i < b.pending_count; ++i) status = worse(status, take(b, b.pending + 3u * i));
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
    return Status::kOk;
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
  for (uint32_t i = 0; i < n; ++i) status = worse(status, push_one(b, xyz + 3u * static_cast<size_t>(i)));
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
  const int64_t last = b.lattice.row_of(b.stats.furthest_along);
  for (; b.next_row <= last; ++b.next_row) status = worse(status, run_row(b, b.next_row));
  b.ring.count = 0;
  b.stats.done_until = static_cast<double>(b.next_row) * b.lattice.core;
  return status;
}

void SceneStream::reset() noexcept {
  if (buffers_ == nullptr) return;
  StreamBuffers& b = *buffers_;
  b.ring.count = 0;
  b.cells.start(b.lattice.own_min - b.lattice.margin);
  b.pending_count = 0;
  b.origin_set = false;
  b.flushed = false;
  b.next_row = 0;
  const size_t used = b.stats.scene.workspace_used;
  b.stats = StreamStats{};
  b.stats.scene.workspace_used = used;
}

const StreamStats& SceneStream::stats() const noexcept {
  return buffers_ == nullptr ? kNoStreamStats : buffers_->stats;
}

}  // namespace spinhash
