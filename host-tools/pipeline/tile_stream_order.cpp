#include "pipeline/tile_stream_order.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "pipeline/spill_folder.hpp"

namespace spinhash::pipeline {

namespace fs = std::filesystem;

namespace {

constexpr double kStep = 1e-3;        // m: the stream's lattice
constexpr double kReach = 2000000.0;  // m: 32-bit steps of 1 mm
constexpr size_t kStepsPerPoint = 3;
// A cell's blocks double from the first to the largest: few blocks for a
// dense cell, little memory unused in a sparse one.
constexpr uint32_t kFirstBlockPoints = 256, kMaxBlockPoints = uint32_t{1} << 16;

bool finite3(const double* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// floor as an integer, for |v| < 2^62: the truncation, one less where it
// rounded up (std::floor is a call on x86-64's baseline, and this runs per point).
int64_t floor_int(double v) {
  const auto t = static_cast<int64_t>(v);
  return static_cast<double>(t) > v ? t - 1 : t;
}

// The nearest step (halves away from zero), for |v| < 2^31.
int32_t nearest_step(double v) { return static_cast<int32_t>(v >= 0.0 ? v + 0.5 : v - 0.5); }

}  // namespace

AlongTrackOrder::AlongTrackOrder(double heading_deg, double row_depth, double column_width,
                                 size_t memory_points)
    : row_depth_(row_depth), column_width_(column_width), memory_points_(memory_points) {
  if (!(row_depth > 0.0) || !(column_width >= 0.0))
    throw std::invalid_argument("along-track order: row depth must be > 0 and column width >= 0");
  if (memory_points == 0)
    throw std::invalid_argument("along-track order: the memory budget must be at least 1 point");
  const double r = heading_deg * (3.14159265358979323846 / 180.0);  // as the stream's frame
  ax_ = std::cos(r);
  ay_ = std::sin(r);
  for (int a = 0; a < 3; ++a) {
    min_[a] = INFINITY;
    max_[a] = -INFINITY;
  }
}

AlongTrackOrder::~AlongTrackOrder() {
  file_.close();
  if (!dir_.empty()) remove_spill_folder(dir_.string());
}

int64_t AlongTrackOrder::column_of(double x, double y) const {
  if (!(column_width_ > 0.0)) return 0;
  return floor_int((-x * ay_ + y * ax_) / column_width_);
}

void AlongTrackOrder::add(const double* xyz, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const double* p = xyz + 3 * i;
    if (!finite3(p)) {
      ++nonfinite_;
      continue;
    }
    if (!origin_set_) {
      for (int a = 0; a < 3; ++a) origin_[a] = std::floor(p[a]);
      origin_set_ = true;
    }
    int32_t k[3];
    double q[3];  // the point as it comes back
    bool near = true;
    for (int a = 0; a < 3; ++a) {
      const double d = p[a] - origin_[a];
      near = near && std::fabs(d) < kReach;
      k[a] = near ? nearest_step(d / kStep) : 0;
      q[a] = origin_[a] + static_cast<double>(k[a]) * kStep;
    }
    if (!near) {
      ++far_;
      continue;
    }
    // The point's cell: its row along, its column across.
    const int64_t row = floor_int((q[0] * ax_ + q[1] * ay_) / row_depth_), column = column_of(q[0], q[1]);
    const auto h = static_cast<uint64_t>(row) * 0x9E3779B97F4A7C15ull + static_cast<uint64_t>(column);
    Recent& r = recent_[(h ^ (h >> 29)) % kRecentCells];
    if (r.held == nullptr || r.row != row || r.column != column) {
      r.held = &cells_[Cell{row, column}];
      r.row = row;
      r.column = column;
    }
    Held& held = *r.held;
    if (held.blocks.empty() || held.blocks.back().points == held.blocks.back().capacity) new_block(held);
    Block& block = held.blocks.back();
    int32_t* to = block.steps + kStepsPerPoint * block.points;
    to[0] = k[0];
    to[1] = k[1];
    to[2] = k[2];
    ++block.points;
    ++held.points;
    for (int a = 0; a < 3; ++a) {
      min_[a] = q[a] < min_[a] ? q[a] : min_[a];
      max_[a] = q[a] > max_[a] ? q[a] : max_[a];
    }
    ++points_;
    if (++held_ >= memory_points_) spill_all();
  }
}

std::map<int64_t, uint64_t> AlongTrackOrder::columns() const {
  std::map<int64_t, uint64_t> points;
  for (const auto& [cell, held] : cells_) points[cell.second] += held.points;
  return points;
}

void AlongTrackOrder::new_block(Held& held) {
  const uint32_t capacity =
      held.blocks.empty() ? kFirstBlockPoints : std::min(2 * held.blocks.back().capacity, kMaxBlockPoints);
  held.blocks.push_back({slabs_.alloc(kStepsPerPoint * capacity), 0, capacity});
}

void AlongTrackOrder::spill_all() {
  if (dir_.empty()) {
    dir_ = make_spill_folder();
    file_path_ = dir_ / "order.xyz";
    file_.open(file_path_, std::ios::binary | std::ios::trunc);
  }
  for (auto& [cell, held] : cells_) {
    if (held.blocks.empty()) continue;
    uint64_t points = 0;
    for (const Block& b : held.blocks) {
      file_.write(reinterpret_cast<const char*>(b.steps),
                  static_cast<std::streamsize>(kStepsPerPoint * b.points * sizeof(int32_t)));
      points += b.points;
    }
    held.spilled.push_back({file_bytes_, points});
    file_bytes_ += kStepsPerPoint * points * sizeof(int32_t);
    held.blocks.clear();
  }
  slabs_.clear();
  file_.flush();  // read back by cursors, through their own streams
  if (!file_) throw std::runtime_error("cannot write " + file_path_.string());
  held_ = 0;
}

AlongTrackOrder::Cursor::Cursor(const AlongTrackOrder& order, int64_t col_lo, int64_t col_hi)
    : order_(&order), col_lo_(col_lo), col_hi_(col_hi), cell_(order.cells_.begin()) {}

size_t AlongTrackOrder::Cursor::read(double* xyz, size_t max_points) {
  size_t got = 0;
  const double o0 = order_->origin_[0], o1 = order_->origin_[1], o2 = order_->origin_[2];
  auto put = [&](const int32_t* k, size_t n) {  // n points of steps into xyz
    double* out = xyz + 3 * got;
    for (size_t i = 0; i < n; ++i) {
      out[3 * i] = o0 + static_cast<double>(k[3 * i]) * kStep;
      out[3 * i + 1] = o1 + static_cast<double>(k[3 * i + 1]) * kStep;
      out[3 * i + 2] = o2 + static_cast<double>(k[3 * i + 2]) * kStep;
    }
    got += n;
  };
  while (got < max_points && cell_ != order_->cells_.end()) {
    const Cell& cell = cell_->first;
    const Held& held = cell_->second;
    if (cell.second < col_lo_ || cell.second > col_hi_) {
      ++cell_;
      continue;
    }
    if (run_ < held.spilled.size()) {  // the cell's runs in the file first
      const Run& run = held.spilled[run_];
      if (!file_.is_open()) {
        file_.open(order_->file_path_, std::ios::binary);
        if (!file_) throw std::runtime_error("cannot read " + order_->file_path_.string());
      }
      const size_t n = static_cast<size_t>(std::min<uint64_t>(max_points - got, run.points - in_run_));
      buf_.resize(kStepsPerPoint * n);
      file_.seekg(static_cast<std::streamoff>(run.offset + in_run_ * kStepsPerPoint * sizeof(int32_t)));
      file_.read(reinterpret_cast<char*>(buf_.data()),
                 static_cast<std::streamsize>(buf_.size() * sizeof(int32_t)));
      if (!file_) throw std::runtime_error("cannot read " + order_->file_path_.string());
      put(buf_.data(), n);
      if ((in_run_ += n) == run.points) {
        ++run_;
        in_run_ = 0;
      }
      continue;
    }
    if (block_ < held.blocks.size()) {
      const Block& block = held.blocks[block_];
      const size_t take = std::min<size_t>(max_points - got, block.points - at_);
      put(block.steps + kStepsPerPoint * at_, take);
      at_ += static_cast<uint32_t>(take);
      if (at_ < block.points) continue;  // filled
      ++block_;
      at_ = 0;
      continue;
    }
    ++cell_;
    run_ = 0;
    block_ = 0;
    at_ = 0;
  }
  return got;
}

void AlongTrackOrder::replay(int64_t col_lo, int64_t col_hi, size_t chunk, const ChunkSink& on_chunk) const {
  Cursor cursor(*this, col_lo, col_hi);
  std::vector<double> buf(3 * chunk);
  for (size_t n; (n = cursor.read(buf.data(), chunk)) > 0;) on_chunk(buf.data(), n);
}

void AlongTrackOrder::replay(size_t chunk, const ChunkSink& on_chunk) const {
  replay(INT64_MIN, INT64_MAX, chunk, on_chunk);
}

}  // namespace spinhash::pipeline
