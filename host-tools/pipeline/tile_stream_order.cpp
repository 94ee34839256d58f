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
  const double r = heading_deg * (3.14159265358979323846 / 180.0);  // as the stream's frame
  ax_ = std::cos(r);
  ay_ = std::sin(r);
  for (int a = 0; a < 3; ++a) {
    min_[a] = INFINITY;
    max_[a] = -INFINITY;
  }
}

AlongTrackOrder::~AlongTrackOrder() {
  if (!dir_.empty()) remove_spill_folder(dir_.string());
}

int64_t AlongTrackOrder::column_of(double x, double y) const {
  if (!(column_width_ > 0.0)) return 0;
  return floor_int((-x * ay_ + y * ax_) / column_width_);
}

AlongTrackOrder::Cell AlongTrackOrder::cell_of(const double* p) const {
  const double s = p[0] * ax_ + p[1] * ay_;
  return {floor_int(s / row_depth_), column_of(p[0], p[1])};
}

fs::path AlongTrackOrder::path_of(const Cell& c) const {
  return dir_ / ("r" + std::to_string(c.first) + "c" + std::to_string(c.second) + ".xyz");
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
    const Cell c = cell_of(q);
    if (last_ == nullptr || c != last_cell_) {
      last_ = &cells_[c];
      last_cell_ = c;
    }
    last_->steps.insert(last_->steps.end(), k, k + 3);
    ++last_->points;
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

void AlongTrackOrder::spill_all() {
  if (dir_.empty()) dir_ = make_spill_folder();
  for (auto& [cell, held] : cells_) {
    if (held.steps.empty()) continue;
    const fs::path path = path_of(cell);
    std::ofstream f(path, std::ios::binary | std::ios::app);
    f.write(reinterpret_cast<const char*>(held.steps.data()),
            static_cast<std::streamsize>(held.steps.size() * sizeof(int32_t)));
    if (!f) throw std::runtime_error("cannot write " + path.string());
    held.spilled = true;
    held.steps.clear();
    held.steps.shrink_to_fit();
  }
  held_ = 0;
}

AlongTrackOrder::Cursor::Cursor(const AlongTrackOrder& order, int64_t col_lo, int64_t col_hi)
    : order_(&order), col_lo_(col_lo), col_hi_(col_hi), cell_(order.cells_.begin()) {}

size_t AlongTrackOrder::Cursor::read(double* xyz, size_t max_points) {
  size_t got = 0;
  const double* o = order_->origin_;
  auto put = [&](const int32_t* k, size_t n) {  // n points of steps into xyz
    for (size_t i = 0; i < n; ++i, ++got)
      for (size_t a = 0; a < kStepsPerPoint; ++a)
        xyz[3 * got + a] = o[a] + static_cast<double>(k[kStepsPerPoint * i + a]) * kStep;
  };
  while (got < max_points && cell_ != order_->cells_.end()) {
    const Cell& cell = cell_->first;
    const Held& held = cell_->second;
    if (cell.second < col_lo_ || cell.second > col_hi_) {
      ++cell_;
      continue;
    }
    if (held.spilled && !opened_) {
      file_.open(order_->path_of(cell), std::ios::binary);
      if (!file_) throw std::runtime_error("cannot read " + order_->path_of(cell).string());
      opened_ = true;
    }
    if (file_.is_open()) {
      buf_.resize(kStepsPerPoint * (max_points - got));
      file_.read(reinterpret_cast<char*>(buf_.data()),
                 static_cast<std::streamsize>(buf_.size() * sizeof(int32_t)));
      put(buf_.data(), static_cast<size_t>(file_.gcount()) / (kStepsPerPoint * sizeof(int32_t)));
      if (file_) continue;  // filled
      file_.close();
      file_.clear();
    }
    const size_t take = std::min(max_points - got, (held.steps.size() - at_) / kStepsPerPoint);
    put(held.steps.data() + at_, take);
    at_ += kStepsPerPoint * take;
    if (at_ < held.steps.size()) continue;  // filled
    ++cell_;
    opened_ = false;
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
