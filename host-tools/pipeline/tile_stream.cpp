#include "pipeline/tile_stream.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>

#include "cloud/metric_source.hpp"
#include "pipeline/object_units.hpp"
#include "pipeline/spill_folder.hpp"
#include "spinhash/scene_fields.h"

#include "spinhash/limits.hpp"

namespace spinhash::pipeline {
namespace {

namespace fs = std::filesystem;

// Sizing the stream from the tile: the densest expected spot over the
// tile's mean density (overlapping flight lines double it), and the bounds.
constexpr double kDensitySafety = 2.5;
constexpr uint64_t kMinWindowPoints = 100000;
constexpr uint64_t kMaxWindowPoints = kMaxSceneTilePoints;
constexpr uint64_t kMinBufferedPoints = 200000;
constexpr uint64_t kMaxBufferedPoints = kMaxStreamBufferedPoints;
// A 32 m cell across the track holding fewer points than this share of the
// tile is an outlier (a GNSS glitch), not part of the swath.
constexpr double kOutlierCellShare = 1e-6;
constexpr uint64_t kMinSwathCellPoints = 2;
// A band of columns streamed at once: 2 cores (64 m) across, plus its
// margins. Wider tiles are cut into bands, each owning its columns, so the
// buffer never holds a row across the whole tile.
constexpr int64_t kBandColumns = 2;
// The spill's rows along the track: the stream's declared lag, since a row's
// points are pushed in any order. Shallow rows let the stream run a row of
// windows soon after its lookahead arrives, so its buffer holds little more
// than what its windows gather.
constexpr double kSpillRowDepth = 8.0;  // m

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool finite3(const double* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// One temporary file per cell of the lattice (rows of kSpillRowDepth along
// x, columns of a window core across, y), written through small buffers so
// that a tile of thousands of cells keeps neither its files open nor its
// points in memory.
class CellSpill {
 public:
  CellSpill(double row_depth, double column_width)
      : row_depth_(row_depth), core_(column_width), dir_(make_spill_folder()) {}
  ~CellSpill() { remove_spill_folder(dir_.string()); }
  CellSpill(const CellSpill&) = delete;
  CellSpill& operator=(const CellSpill&) = delete;

  int64_t row_of(double x) const { return static_cast<int64_t>(std::floor(x / row_depth_)); }
  int64_t cell_of(double y) const { return static_cast<int64_t>(std::floor(y / core_)); }
  void append(const double* p) {
    const Cell c{row_of(p[0]), cell_of(p[1])};
    std::vector<double>& buf = cells_[c];
    buf.insert(buf.end(), p, p + 3);
    ++buffered_;
    if (buf.size() >= 3 * kCellBufferPoints) write_out(c, buf);
    if (buffered_ >= kSpillBufferPoints) finish();  // a wide tile's many cells: all out at once
  }
  void finish() {
    for (auto& kv : cells_) write_out(kv.first, kv.second);
  }
  std::vector<int64_t> rows() const {
    std::vector<int64_t> r;
    for (const auto& kv : cells_)
      if (r.empty() || r.back() != kv.first.first) r.push_back(kv.first.first);
    return r;
  }
  // Hands the cell's points out in chunks (none when the cell is empty).
  template <class F>
  void read(int64_t row, int64_t col, size_t chunk, F&& on_chunk) const {
    if (cells_.count({row, col}) == 0) return;
    std::ifstream in(path({row, col}), std::ios::binary);
    std::vector<double> buf(3 * chunk);
    while (in) {
      in.read(reinterpret_cast<char*>(buf.data()), static_cast<std::streamsize>(buf.size() * sizeof(double)));
      const size_t got = static_cast<size_t>(in.gcount()) / (3 * sizeof(double));
      if (got > 0) on_chunk(buf.data(), got);
    }
  }

 private:
  using Cell = std::pair<int64_t, int64_t>;
  static constexpr size_t kCellBufferPoints = 256;        // 6 KB per cell in memory
  static constexpr size_t kSpillBufferPoints = 1u << 18;  // 6 MB over all cells, whatever the tile's size

  fs::path path(const Cell& c) const {
    return dir_ / ("r" + std::to_string(c.first) + "c" + std::to_string(c.second) + ".xyz");
  }
  void write_out(const Cell& c, std::vector<double>& buf) {
    if (buf.empty()) return;
    std::ofstream f(path(c), std::ios::binary | std::ios::app);
    f.write(reinterpret_cast<const char*>(buf.data()),
            static_cast<std::streamsize>(buf.size() * sizeof(double)));
    if (!f) throw std::runtime_error("cannot write " + path(c).string());
    buffered_ -= buf.size() / 3;
    buf.clear();
    buf.shrink_to_fit();
  }

  double row_depth_, core_;
  size_t buffered_ = 0;  // points held in the cells' buffers
  fs::path dir_;
  std::map<Cell, std::vector<double>> cells_;  // ordered: rows, then columns
};

// What the spill pass learns of the tile.
struct TileExtent {
  uint64_t finite = 0, nonfinite = 0;
  double xmin = INFINITY, xmax = -INFINITY, zmin = INFINITY;
  std::map<int64_t, uint64_t> across;  // points per core-wide cell across the track (y)
};

void spill(host::PointSource& source, size_t chunk, uint32_t picture_points, CellSpill& cells, TileExtent& e,
           TileStreamResult& res) {
  const uint64_t declared = source.header().count_known ? source.header().point_count : 0;
  const uint64_t every = picture_points > 0 && declared > picture_points ? declared / picture_points : 1;
  std::vector<double> buf(3 * chunk);
  for (size_t got; (got = source.read(buf.data(), chunk)) > 0;) {
    for (size_t i = 0; i < got; ++i) {
      const double* p = buf.data() + 3 * i;
      if (picture_points > 0 && (res.points_read + i) % every == 0)
        res.picture_xyz.insert(res.picture_xyz.end(), p, p + 3);
      if (!finite3(p)) {
        ++e.nonfinite;
        continue;
      }
      cells.append(p);
      ++e.finite;
      e.xmin = std::min(e.xmin, p[0]);
      e.xmax = std::max(e.xmax, p[0]);
      e.zmin = std::min(e.zmin, p[2]);
      ++e.across[cells.cell_of(p[1])];
    }
    res.points_read += got;
  }
  cells.finish();
}

// Cells of a grid of `cell` m over w x h m, with the snap's extra rows.
uint32_t grid_cells(double w, double h, float cell) {
  const double cells = (std::ceil(w / cell) + 2.0) * (std::ceil(h / cell) + 2.0);
  return static_cast<uint32_t>(std::min(cells, 16777216.0));
}

// The columns (cells across the track) holding more than outliers.
struct Swath {
  int64_t lo = 0, hi = 0;
};

Swath swath_columns(const TileExtent& e) {
  const uint64_t floor_count =
      std::max<uint64_t>(kMinSwathCellPoints, static_cast<uint64_t>(kOutlierCellShare * e.finite));
  Swath sw{0, -1};
  for (const auto& kv : e.across)
    if (kv.second >= floor_count) {
      if (sw.hi < sw.lo) sw.lo = kv.first;
      sw.hi = kv.first;
    }
  if (sw.hi < sw.lo) sw.lo = sw.hi = e.across.empty() ? 0 : e.across.begin()->first;
  return sw;
}

// The stream's config for one band of columns [band_lo, band_hi] of the
// tile: frame on the absolute lattice (origin at the swath's first column),
// the band owned, its margins seen, buffers sized from the tile's density
// over a band (never over the tile).
StreamConfig band_config(const TileStreamOptions& o, const TileExtent& e, const Swath& sw, int64_t band_lo,
                         int64_t band_hi) {
  StreamConfig c;
  c.scene = o.scene;
  const double core = o.scene.window_core, margin = o.scene.window_margin;
  c.origin_given = true;
  c.origin[0] = std::floor(e.xmin / core) * core;
  c.origin[1] = static_cast<double>(sw.lo) * core;
  c.origin[2] = e.zmin;
  c.heading_deg = 0.0f;  // rows along x
  c.own_min = static_cast<float>(static_cast<double>(band_lo - sw.lo) * core);
  c.own_max = static_cast<float>(static_cast<double>(band_hi + 1 - sw.lo) * core);
  c.swath_min = c.own_min - static_cast<float>(margin);
  c.swath_max = c.own_max + static_cast<float>(margin);
  c.max_lag = static_cast<float>(kSpillRowDepth);                 // a spill row's points come in any order
  c.max_jump = static_cast<float>(e.xmax - e.xmin + 2.0 * core);  // the tile's extent is known
  const double width = static_cast<double>(sw.hi - sw.lo + 1) * core,
               length = std::max(core, e.xmax - e.xmin);
  const double density = static_cast<double>(e.finite) / (width * length) * kDensitySafety;
  // A window gathers its core and object margin; the buffer holds a row's
  // gathered points, its terrain lookahead and the lag, across the band and
  // its margins (points across beyond the gathered band are forgotten once
  // their terrain cells are summed: reserved here, seldom touched).
  const double gathered = core + 2.0 * o.scene.object_margin;
  const double window_area = gathered * gathered;
  const double band_width = std::min(width, static_cast<double>(kBandColumns) * core) + 2.0 * margin;
  const double buffer_area = (core + o.scene.object_margin + margin + kSpillRowDepth) * band_width;
  // The segmentation grid holds a whole window, the terrain grid the band's
  // windows side by side (one strip per row), whatever their size.
  const double seen = core + 2.0 * margin;
  c.scene.max_terrain_cells =
      std::max<uint32_t>(c.scene.max_terrain_cells, grid_cells(band_width, seen, o.scene.terrain_cell));
  c.scene.max_segment_cells =
      std::max<uint32_t>(c.scene.max_segment_cells, grid_cells(gathered, gathered, o.scene.segment_cell));
  if (c.scene.max_tile_points == 0)
    c.scene.max_tile_points =
        static_cast<uint32_t>(std::clamp<double>(density * window_area, kMinWindowPoints, kMaxWindowPoints));
  const uint64_t buffered = o.max_buffered_points > 0
                                ? o.max_buffered_points
                                : static_cast<uint64_t>(std::clamp<double>(
                                      density * buffer_area, kMinBufferedPoints, kMaxBufferedPoints));
  c.max_buffered_points = static_cast<uint32_t>(std::min<uint64_t>(buffered, kMaxBufferedPoints));
  return c;
}

uint32_t add32(uint32_t a, uint32_t b) {
  const uint64_t s = static_cast<uint64_t>(a) + b;
  return s > 0xFFFFFFFFull ? 0xFFFFFFFFu : static_cast<uint32_t>(s);
}

// Sums one band's counts into the tile's, field by field from the one list
// (scene_fields.h): counts add (32-bit ones saturate), positions along the
// line take the furthest, the workspace is the tile's own (not a sum).
void add_field_U32(uint32_t& into, uint32_t b) { into = add32(into, b); }
void add_field_U64(uint64_t& into, uint64_t b) { into += b; }
void add_field_F64(double& into, double b) { into = std::max(into, b); }
void add_field_SIZE(size_t&, size_t) {}
void add_field_KINDS(uint32_t (&into)[kObjectKinds], const uint32_t (&b)[kObjectKinds]) {
  for (uint32_t k = 0; k < kObjectKinds; ++k) into[k] = add32(into[k], b[k]);
}
void add_field_SCENE(SceneStats& into, const SceneStats& b) {
#define SPINHASH_ADD(kind, name, json) add_field_##kind(into.name, b.name);
  SPINHASH_SCENE_STATS_FIELDS(SPINHASH_ADD)
#undef SPINHASH_ADD
}

void accumulate(StreamStats& into, const StreamStats& b) {
#define SPINHASH_ADD(kind, name, json) add_field_##kind(into.name, b.name);
  SPINHASH_STREAM_STATS_FIELDS(SPINHASH_ADD)
#undef SPINHASH_ADD
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

// Streams one band: rows in order, each row's cells across the band and its
// margins, only the points within the band's swath.
Status stream_band(const Database& db, const CellSpill& cells, const StreamConfig& config, const Swath& sw,
                   size_t chunk, void* workspace, size_t bytes, const ObjectCallback& on_object,
                   StreamStats* stats) {
  SceneStream stream;
  Status status =
      stream.init(&db, config, workspace, bytes, forward, const_cast<ObjectCallback*>(&on_object));
  if (status != Status::kOk) return status;
  const double core = config.scene.window_core;
  const int64_t col_lo = sw.lo + static_cast<int64_t>(std::floor(config.swath_min / core));
  const int64_t col_hi = sw.lo + static_cast<int64_t>(std::ceil(config.swath_max / core)) - 1;
  const double t_lo = config.origin[1] + config.swath_min, t_hi = config.origin[1] + config.swath_max;
  std::vector<double> kept;
  for (int64_t row : cells.rows())
    for (int64_t col = std::max(col_lo, sw.lo); col <= std::min(col_hi, sw.hi); ++col)
      cells.read(row, col, chunk, [&](const double* xyz, size_t n) {
        kept.clear();
        for (size_t i = 0; i < n; ++i)
          if (xyz[3 * i + 1] >= t_lo && xyz[3 * i + 1] < t_hi)
            kept.insert(kept.end(), xyz + 3 * i, xyz + 3 * i + 3);
        status = worse(status, stream.push(kept.data(), static_cast<uint32_t>(kept.size() / 3)));
      });
  status = worse(status, stream.flush());
  accumulate(*stats, stream.stats());
  return status;
}

}  // namespace

TileStreamResult stream_tile(const Database& db, host::PointSource& source, const TileStreamOptions& options,
                             const ObjectCallback& on_object) {
  TileStreamResult res;
  const auto t0 = std::chrono::steady_clock::now();
  CellSpill cells(kSpillRowDepth, options.scene.window_core);
  TileExtent extent;
  host::MetricSource metric(source, options.units);
  spill(metric, options.chunk_points, options.picture_points, cells, extent, res);
  for (size_t i = 0; i + 3 <= res.picture_xyz.size(); i += 3)
    host::scale_to_file_units(options.units, &res.picture_xyz[i]);
  res.read_ms = ms_since(t0);
  res.stats.scene.points_nonfinite = static_cast<uint32_t>(std::min<uint64_t>(extent.nonfinite, 0xFFFFFFFFu));
  if (extent.finite == 0) {
    res.status = Status::kEmptyCloud;
    res.stats.points_pushed = res.points_read;
    return res;
  }
  const auto t1 = std::chrono::steady_clock::now();
  const Swath sw = swath_columns(extent);
  for (const auto& kv : extent.across)
    if (kv.first < sw.lo || kv.first > sw.hi) res.stats.points_outside += kv.second;  // outliers across
  const StreamConfig first =
      band_config(options, extent, sw, sw.lo, std::min(sw.hi, sw.lo + kBandColumns - 1));
  res.workspace_bytes = required_stream_workspace_bytes(first);
  if (res.workspace_bytes == 0) throw std::runtime_error("invalid scene configuration for this tile");
  auto workspace = lazy_workspace(res.workspace_bytes);
  res.status = Status::kOk;
  std::vector<RankedModel> ranking;
  const ObjectCallback owned = [&](const SceneObject& metres) {
    const SceneObject o = in_file_units(metres, options.units, &ranking);
    const bool mine =
        !options.own_given || (o.center[0] >= options.own_min[0] && o.center[0] < options.own_max[0] &&
                               o.center[1] >= options.own_min[1] && o.center[1] < options.own_max[1]);
    if (mine)
      on_object(o);
    else
      ++res.objects_not_owned;
  };
  for (int64_t lo = sw.lo; lo <= sw.hi; lo += kBandColumns) {
    const StreamConfig band = band_config(options, extent, sw, lo, std::min(sw.hi, lo + kBandColumns - 1));
    res.status = worse(res.status, stream_band(db, cells, band, sw, options.chunk_points, workspace.get(),
                                               res.workspace_bytes, owned, &res.stats));
    ++res.bands;
  }
  res.stats.points_pushed += extent.nonfinite;
  res.stream_ms = ms_since(t1);
  return res;
}

}  // namespace spinhash::pipeline
