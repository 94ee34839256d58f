// The along-track order a SceneStream needs (scene_stream.hpp, its ordering
// contract), for points that come in any order and in chunks of any size:
// each finite point goes to a cell of the frame's lattice (rows of
// row_depth along track, columns of column_width across, both from the
// frame's axes through (0, 0)); the cells stay in memory up to a budget of
// points, then spill to temporary files; rows come back in order, the
// points of a row cell by cell in the order they came. A row spans
// row_depth along track, so the rows handed back in order keep every point
// within row_depth of the furthest: push them into a stream whose max_lag
// is at least row_depth. Memory: the budget, whatever the number of points.
// Used by `spinhash scene`, the survey and Python (AlongTrackOrder,
// SceneRecognizer.push).
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace spinhash::pipeline {

// Points held in memory before the cells spill to files (24 B each).
constexpr size_t kOrderMemoryPoints = size_t{1} << 18;

class AlongTrackOrder {
 public:
  // heading_deg: the along-track direction, degrees from +x
  // (counter-clockwise); row_depth > 0 (m); column_width (m), 0: one column.
  AlongTrackOrder(double heading_deg, double row_depth, double column_width = 0.0,
                  size_t memory_points = kOrderMemoryPoints);
  ~AlongTrackOrder();  // removes its files
  AlongTrackOrder(const AlongTrackOrder&) = delete;
  AlongTrackOrder& operator=(const AlongTrackOrder&) = delete;

  // Takes n points (x y z); non-finite ones are counted and left out.
  // Throws std::runtime_error when a temporary file cannot be written.
  void add(const double* xyz, size_t n);

  uint64_t points() const { return points_; }        // finite points taken
  uint64_t nonfinite() const { return nonfinite_; }  // left out
  const double* min() const { return min_; }         // of the finite points (x y z)
  const double* max() const { return max_; }
  // Finite points per column (absent: none), columns in order.
  const std::map<int64_t, uint64_t>& columns() const { return column_points_; }
  int64_t column_of(double x, double y) const;

  using Cell = std::pair<int64_t, int64_t>;  // row along, column across
  struct Held {
    std::vector<double> xyz;  // in memory, after what the file holds
    bool spilled = false;     // the cell's file holds its first points
  };

  // Reads the points of columns [col_lo, col_hi] back row by row in order,
  // each row's cells by column. The order must outlive it and take no more
  // points meanwhile.
  class Cursor {
   public:
    Cursor(const AlongTrackOrder& order, int64_t col_lo, int64_t col_hi);
    // Up to max_points points (x y z) into xyz; 0 at the end. Throws
    // std::runtime_error when a temporary file cannot be read.
    size_t read(double* xyz, size_t max_points);

   private:
    const AlongTrackOrder* order_;
    int64_t col_lo_, col_hi_;
    std::map<Cell, Held>::const_iterator cell_;
    std::ifstream file_;
    bool opened_ = false;  // the current cell's file, when it has one
    size_t at_ = 0;        // the next of its points in memory (doubles)
  };

  // The same through a callback, in chunks of at most `chunk` points.
  using ChunkSink = std::function<void(const double* xyz, size_t n)>;
  void replay(int64_t col_lo, int64_t col_hi, size_t chunk, const ChunkSink& on_chunk) const;
  // Every column.
  void replay(size_t chunk, const ChunkSink& on_chunk) const;

 private:
  Cell cell_of(const double* p) const;
  void spill_all();
  std::filesystem::path path_of(const Cell& c) const;

  double ax_ = 1.0, ay_ = 0.0;  // the along-track axis
  double row_depth_, column_width_;
  size_t memory_points_;
  size_t held_ = 0;  // points in memory
  uint64_t points_ = 0, nonfinite_ = 0;
  double min_[3], max_[3];
  std::map<Cell, Held> cells_;  // ordered: rows, then columns
  std::map<int64_t, uint64_t> column_points_;
  Held* last_ = nullptr;  // the cell of the previous point (scan order stays in one cell)
  Cell last_cell_{0, 0};
  std::filesystem::path dir_;  // made at the first spill
};

}  // namespace spinhash::pipeline
