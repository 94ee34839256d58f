#include "pipeline/tile_stream.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include "cloud/metric_source.hpp"
#include "pipeline/object_units.hpp"
#include "pipeline/segment_cell.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/scene_tile.hpp"

namespace spinhash::pipeline {
namespace {

// Sizing the stream from the tile: the densest expected spot over the
// tile's mean density (overlapping flight lines double it), and the bounds.
constexpr double kDensitySafety = 2.5;
constexpr uint64_t kMinWindowPoints = 100000;
constexpr uint64_t kMaxWindowPoints = kMaxSceneTilePoints;
constexpr uint64_t kMinBufferedPoints = 200000;
constexpr uint64_t kMaxBufferedPoints = kMaxStreamBufferedPoints;

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The window capacity and the buffer from the tile's density: what a
// window's gather and a band's rows hold at the densest expected spot.
void size_from_density(const AlongTrackOrder& order, const TileStreamOptions& o, SceneConfig* scene,
                       uint32_t* buffered) {
  const double core = o.scene.window_core;
  const double width = std::max(core, order.max()[1] - order.min()[1]),
               length = std::max(core, order.max()[0] - order.min()[0]);
  const double density = static_cast<double>(order.points()) / (width * length) * kDensitySafety;
  const double gathered = core + 2.0 * o.scene.object_margin;
  if (scene->max_tile_points == 0)
    scene->max_tile_points = static_cast<uint32_t>(
        std::clamp<double>(density * gathered * gathered, kMinWindowPoints, kMaxWindowPoints));
  const StreamConfig derived = tile_stream_config(*scene, 0);  // the buffer at a window's density
  const double window = static_cast<double>(scene->max_tile_points);
  const double per_window = static_cast<double>(derived.max_buffered_points) / window;
  const uint64_t want =
      o.max_buffered_points > 0
          ? o.max_buffered_points
          : static_cast<uint64_t>(std::clamp<double>(density * gathered * gathered * per_window,
                                                     kMinBufferedPoints, kMaxBufferedPoints));
  *buffered = static_cast<uint32_t>(std::min<uint64_t>(want, kMaxBufferedPoints));
}

struct FreeDelete {
  void operator()(uint8_t* p) const { std::free(p); }
};

// Uninitialised, so pages the stream never touches cost no memory.
std::unique_ptr<uint8_t, FreeDelete> lazy_workspace(size_t bytes) {
  const size_t rounded = (bytes + kBufferAlignment - 1) / kBufferAlignment * kBufferAlignment;
  auto* p = static_cast<uint8_t*>(std::aligned_alloc(kBufferAlignment, rounded));
  if (p == nullptr) throw std::runtime_error("cannot allocate the stream's workspace");
  return std::unique_ptr<uint8_t, FreeDelete>(p);
}

void forward(void* context, const SceneObject& object, int64_t, uint32_t) {
  (*static_cast<const ObjectCallback*>(context))(object);
}

Status worse(Status a, Status b) { return a == Status::kOk ? b : a; }

// The bands whose windows gather points: for each column of the order that
// holds points, the bands whose columns or object margins meet it.
std::set<uint32_t> bands_with_points(const AlongTrackOrder& order, const TilePlan& plan, double core) {
  std::set<uint32_t> bands;
  for (const auto& [column, points] : order.columns()) {
    if (points == 0) continue;
    const double y0 = static_cast<double>(column) * core, y1 = y0 + core;
    const uint32_t first = tile_band_gathering(plan, y0);
    for (uint32_t b = first; b < plan.bands; ++b) {
      const double band_y = plan.origin[1] + static_cast<double>(b) * plan.band_width;
      if (band_y - plan.object_margin >= y1) break;
      bands.insert(b);
    }
  }
  return bands;
}

}  // namespace

PointSample::PointSample(uint32_t target, uint64_t expected) : target_(target) {
  if (target_ > 0 && expected > target_) every_ = expected / target_;
}

void PointSample::add(const double* p) {
  if (target_ == 0) return;
  if (seen_++ % every_ != 0) return;
  xyz_.insert(xyz_.end(), p, p + 3);
  if (xyz_.size() / 3 <= 2 * target_) return;
  // Every other kept point: those at multiples of twice the step.
  size_t kept = 0;
  for (size_t i = 0; i < xyz_.size(); i += 6, ++kept)
    for (int a = 0; a < 3; ++a) xyz_[3 * kept + a] = xyz_[i + a];
  xyz_.resize(3 * kept);
  every_ *= 2;
}

TileStreamer::TileStreamer(const TileStreamOptions& options, uint64_t expected_points)
    : options_(options),
      order_(0.0, options.scene.row_depth, options.scene.window_core, options.order_memory_points),
      picture_(options.picture_points, expected_points),
      start_(std::chrono::steady_clock::now()) {}

void TileStreamer::add(const double* xyz, size_t n) {
  if (options_.picture_points > 0)
    for (size_t i = 0; i < n; ++i) picture_.add(xyz + 3 * i);
  order_.add(xyz, n);
  added_ += n;
}

TileStreamResult TileStreamer::finish(const Database& db, const ObjectCallback& on_object) {
  TileStreamResult res;
  res.points_read = added_;
  res.picture_xyz = picture_.take();
  for (size_t i = 0; i + 3 <= res.picture_xyz.size(); i += 3)
    host::scale_to_file_units(options_.units, &res.picture_xyz[i]);
  res.read_ms = ms_since(start_);
  const auto streamed = std::chrono::steady_clock::now();
  res.stats.points_pushed = added_;
  res.stats.scene.points_nonfinite =
      static_cast<uint32_t>(std::min<uint64_t>(order_.nonfinite(), 0xFFFFFFFFu));
  res.stats.points_outside = order_.far();  // beyond 2 000 km of the tile's first point
  if (order_.points() == 0) {
    res.status = Status::kEmptyCloud;
    return res;
  }
  SceneConfig scene = options_.scene;
  const double* lo = order_.min();
  const double* hi = order_.max();
  res.density = tile_density(order_.points(), (hi[0] - lo[0]) * (hi[1] - lo[1]));
  if (options_.segment_cell_from_density)
    scene.segment_cell = segment_cell_for_density(scene.segment_cell, res.density, scene.window_core);
  res.segment_cell = scene.segment_cell;
  fit_tile_grids(&scene);
  uint32_t buffered = 0;
  size_from_density(order_, options_, &scene, &buffered);
  const TilePlan plan = plan_tile(scene, order_.min(), order_.max());
  const StreamConfig config = tile_stream_config(scene, buffered);
  res.workspace_bytes = required_stream_workspace_bytes(config);
  if (res.workspace_bytes == 0) throw std::runtime_error("invalid scene configuration for this tile");
  auto workspace = lazy_workspace(res.workspace_bytes);
  std::vector<RankedModel> ranking;
  const ObjectCallback owned = [&](const SceneObject& metres) {
    const SceneObject o = in_file_units(metres, options_.units, &ranking);
    if (!options_.owners.empty()) {
      const uint32_t owner = owner_of(options_.owners.data(), static_cast<uint32_t>(options_.owners.size()),
                                      o.center[0], o.center[1], options_.owner_tolerance);
      if (owner != options_.self) {
        ++(owner == kNoOwner ? res.objects_in_holes : res.objects_not_owned);
        return;
      }
    }
    on_object(o);
  };
  SceneStream stream;
  res.status = stream.init(&db, config, workspace.get(), res.workspace_bytes, forward,
                           const_cast<ObjectCallback*>(&owned));
  if (res.status != Status::kOk) return res;
  const double core = scene.window_core;
  const double t0 = config.swath_min, t1 = config.swath_max;
  const size_t chunk = options_.chunk_points;
  std::vector<double> buf(3 * chunk), kept(3 * chunk);
  for (uint32_t band : bands_with_points(order_, plan, core)) {
    double origin[3];
    tile_band_origin(plan, band, origin);
    stream.reset(origin);
    Status status = Status::kOk;
    const auto col_lo = static_cast<int64_t>(std::floor((origin[1] + t0) / core)),
               col_hi = static_cast<int64_t>(std::floor((origin[1] + t1) / core));
    AlongTrackOrder::Cursor rows(order_, col_lo, col_hi);
    for (size_t n; (n = rows.read(buf.data(), chunk)) > 0;) {
      size_t taken = 0;
      for (size_t i = 0; i < n; ++i) {
        const double t = buf[3 * i + 1] - origin[1];  // across, as the stream's frame has it
        if (t >= t0 && t < t1) std::copy_n(&buf[3 * i], 3, &kept[3 * taken++]);
      }
      status = worse(status, stream.push(kept.data(), static_cast<uint32_t>(taken)));
    }
    status = worse(status, stream.flush());
    add_stream_stats(res.stats, stream.stats());
    res.status = worse(res.status, status);
    ++res.bands;
  }
  res.stats.points_pushed = added_;  // once, though the bands' swaths overlap
  res.stats.points_outside += order_.far();
  res.stats.scene.points_nonfinite =
      static_cast<uint32_t>(std::min<uint64_t>(order_.nonfinite(), 0xFFFFFFFFu));
  res.stream_ms = ms_since(streamed);
  return res;
}

TileStreamResult stream_tile(const Database& db, host::PointSource& source, const TileStreamOptions& options,
                             const ObjectCallback& on_object) {
  const uint64_t declared = source.header().count_known ? source.header().point_count : 0;
  TileStreamer tile(options, declared);
  host::MetricSource metric(source, options.units);
  std::vector<double> buf(3 * options.chunk_points);
  for (size_t got; (got = metric.read(buf.data(), options.chunk_points)) > 0;) tile.add(buf.data(), got);
  return tile.finish(db, on_object);
}

}  // namespace spinhash::pipeline
