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

namespace spinhash::pipeline {
namespace {

namespace fs = std::filesystem;

// Sizing the stream from the tile: the densest expected spot over the
// tile's mean density (overlapping flight lines double it), and the bounds.
constexpr double kDensitySafety = 2.5;
constexpr uint64_t kMinWindowPoints = 100000;
constexpr uint64_t kMaxWindowPoints = 1u << 26;
constexpr uint64_t kMinBufferedPoints = 200000;
constexpr uint64_t kMaxBufferedPoints = 1u << 28;
// A 32 m cell across the track holding fewer points than this share of the
// tile is an outlier (a GNSS glitch), not part of the swath.
constexpr double kOutlierCellShare = 1e-6;
constexpr uint64_t kMinSwathCellPoints = 2;

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool finite3(const double* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// One temporary file per row of the lattice, removed with the object.
class RowSpill {
 public:
  explicit RowSpill(double core) : core_(core) {
    std::string pattern = (fs::temp_directory_path() / "spinhash-scene-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a temporary folder");
    dir_ = pattern;
  }
  ~RowSpill() {
    files_.clear();
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  RowSpill(const RowSpill&) = delete;
  RowSpill& operator=(const RowSpill&) = delete;

  int64_t row_of(double x) const { return static_cast<int64_t>(std::floor(x / core_)); }
  void append(const double* p) {
    std::ofstream& f = file(row_of(p[0]));
    f.write(reinterpret_cast<const char*>(p), 3 * sizeof(double));
    if (!f) throw std::runtime_error("cannot write " + path(row_of(p[0])).string());
  }
  std::vector<int64_t> rows() const {
    std::vector<int64_t> r;
    for (const auto& kv : files_) r.push_back(kv.first);
    return r;
  }
  // Closes the row's file and hands its points out in chunks.
  template <class F>
  void read(int64_t row, size_t chunk, F&& on_chunk) {
    files_.erase(row);
    std::ifstream in(path(row), std::ios::binary);
    std::vector<double> buf(3 * chunk);
    while (in) {
      in.read(reinterpret_cast<char*>(buf.data()), static_cast<std::streamsize>(buf.size() * sizeof(double)));
      const size_t got = static_cast<size_t>(in.gcount()) / (3 * sizeof(double));
      if (got > 0) on_chunk(buf.data(), got);
    }
    std::error_code ec;
    fs::remove(path(row), ec);
  }

 private:
  fs::path path(int64_t row) const { return dir_ / ("row" + std::to_string(row) + ".xyz"); }
  std::ofstream& file(int64_t row) {
    auto it = files_.find(row);
    if (it == files_.end()) {
      it = files_.emplace(row, std::ofstream(path(row), std::ios::binary)).first;
      if (!it->second) throw std::runtime_error("cannot write " + path(row).string());
    }
    return it->second;
  }

  double core_;
  fs::path dir_;
  std::map<int64_t, std::ofstream> files_;
};

// What the spill pass learns of the tile.
struct TileExtent {
  uint64_t finite = 0, nonfinite = 0;
  double xmin = INFINITY, xmax = -INFINITY, zmin = INFINITY;
  std::map<int64_t, uint64_t> across;  // points per core-wide cell across the track (y)
};

void spill(host::PointSource& source, size_t chunk, uint32_t picture_points, RowSpill& rows, TileExtent& e,
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
      rows.append(p);
      ++e.finite;
      e.xmin = std::min(e.xmin, p[0]);
      e.xmax = std::max(e.xmax, p[0]);
      e.zmin = std::min(e.zmin, p[2]);
      ++e.across[rows.row_of(p[1])];
    }
    res.points_read += got;
  }
}

// The stream's config for the tile: frame on the absolute lattice, swath
// over the cells across the track that hold more than outliers, buffers
// sized from the density.
StreamConfig tile_config(const TileStreamOptions& o, const TileExtent& e) {
  StreamConfig c;
  c.scene = o.scene;
  const double core = o.scene.window_core, margin = o.scene.window_margin;
  const uint64_t floor_count =
      std::max<uint64_t>(kMinSwathCellPoints, static_cast<uint64_t>(kOutlierCellShare * e.finite));
  int64_t lo = 0, hi = -1;
  for (const auto& kv : e.across)
    if (kv.second >= floor_count) {
      if (hi < lo) lo = kv.first;
      hi = kv.first;
    }
  if (hi < lo) lo = hi = e.across.empty() ? 0 : e.across.begin()->first;
  c.origin_given = true;
  c.origin[0] = std::floor(e.xmin / core) * core;
  c.origin[1] = static_cast<double>(lo) * core;
  c.origin[2] = e.zmin;
  c.heading_deg = 0.0f;  // rows along x
  c.swath_min = c.own_min = 0.0f;
  c.swath_max = c.own_max = static_cast<float>(static_cast<double>(hi - lo + 1) * core);
  c.max_lag = static_cast<float>(core);                           // a row's points come in any order
  c.max_jump = static_cast<float>(e.xmax - e.xmin + 2.0 * core);  // the tile's extent is known
  const double width = static_cast<double>(c.swath_max), length = std::max(core, e.xmax - e.xmin);
  const double density = static_cast<double>(e.finite) / (width * length) * kDensitySafety;
  const double window_area = (core + 2.0 * margin) * (core + 2.0 * margin);
  const double buffer_area = (2.0 * core + 2.0 * margin) * (width + 2.0 * margin);
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

}  // namespace

TileStreamResult stream_tile(const Database& db, host::PointSource& source, const TileStreamOptions& options,
                             const ObjectCallback& on_object) {
  TileStreamResult res;
  const auto t0 = std::chrono::steady_clock::now();
  RowSpill rows(options.scene.window_core);
  TileExtent extent;
  spill(source, options.chunk_points, options.picture_points, rows, extent, res);
  res.read_ms = ms_since(t0);
  if (extent.finite == 0) {
    res.status = Status::kEmptyCloud;
    res.stats.points_pushed = res.points_read;
    res.stats.scene.points_nonfinite =
        static_cast<uint32_t>(std::min<uint64_t>(extent.nonfinite, 0xFFFFFFFFu));
    return res;
  }
  const auto t1 = std::chrono::steady_clock::now();
  const StreamConfig config = tile_config(options, extent);
  res.workspace_bytes = required_stream_workspace_bytes(config);
  if (res.workspace_bytes == 0) throw std::runtime_error("invalid scene configuration for this tile");
  auto workspace = lazy_workspace(res.workspace_bytes);
  SceneStream stream;
  res.status = stream.init(&db, config, workspace.get(), res.workspace_bytes, forward,
                           const_cast<ObjectCallback*>(&on_object));
  if (res.status != Status::kOk) return res;
  for (int64_t row : rows.rows())
    rows.read(row, options.chunk_points, [&](const double* xyz, size_t n) {
      res.status = worse(res.status, stream.push(xyz, static_cast<uint32_t>(n)));
    });
  res.status = worse(res.status, stream.flush());
  res.stats = stream.stats();
  res.stats.points_pushed += extent.nonfinite;
  res.stats.scene.points_nonfinite +=
      static_cast<uint32_t>(std::min<uint64_t>(extent.nonfinite, 0xFFFFFFFFu));
  res.stream_ms = ms_since(t1);
  return res;
}

}  // namespace spinhash::pipeline
