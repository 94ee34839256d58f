// The along-track order a SceneStream needs (scene_stream.hpp, its ordering
// contract), for points that come in any order and in chunks of any size:
// each finite point goes to a cell of the frame's lattice (rows of
// row_depth along track, columns of column_width across, both from the
// frame's axes through (0, 0)); the cells stay in memory up to a budget of
// points, then spill to a temporary file (each cell's held points as one
// run, appended); rows come back in order, the points of a row cell by
// cell in the order they came. Points are held as
// 32-bit steps of 1 mm from the first point's metre (12 B a point): the
// stream's own lattice (scene/window_lattice.hpp), within 2 000 km of it
// (farther points are counted and left out). A row spans
// row_depth along track, so the rows handed back in order keep every point
// within row_depth of the furthest: push them into a stream whose max_lag
// is at least row_depth. Memory: the budget's points (a cell's blocks double as
// it fills, so up to twice their 12 B), whatever the number of points.
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

#include "pipeline/step_slabs.hpp"

namespace spinhash::pipeline {

// Points held in memory before the cells spill to the file (12 B each,
// 48 MB): large enough that a dense tile spills once or not at all, each
// spill one sequential write.
constexpr size_t kOrderMemoryPoints = size_t{1} << 22;
// Bounds of the budget the command line takes (`--order-memory`): smaller
// budgets spill more often, larger ones hold up to 12 GB.
constexpr size_t kMinOrderMemoryPoints = size_t{1} << 12;
constexpr size_t kMaxOrderMemoryPoints = size_t{1} << 30;

class AlongTrackOrder {
 public:
  // heading_deg: the along-track direction, degrees from +x
  // (counter-clockwise); row_depth > 0 (m); column_width (m), 0: one column.
  AlongTrackOrder(double heading_deg, double row_depth, double column_width = 0.0,
                  size_t memory_points = kOrderMemoryPoints);
  ~AlongTrackOrder();  // removes its files
  AlongTrackOrder(const AlongTrackOrder&) = delete;
  AlongTrackOrder& operator=(const AlongTrackOrder&) = delete;

  // Takes n points (x y z); non-finite ones, and those beyond 2 000 km of
  // the first, are counted and left out. Throws std::runtime_error when the
  // temporary file cannot be written.
  void add(const double* xyz, size_t n);

  uint64_t points() const { return points_; }        // points taken
  uint64_t nonfinite() const { return nonfinite_; }  // left out
  uint64_t far() const { return far_; }              // left out: beyond the 32-bit steps' reach
  const double* min() const { return min_; }         // of the points taken (x y z)
  const double* max() const { return max_; }
  // Points per column (absent: none), columns in order.
  std::map<int64_t, uint64_t> columns() const;
  int64_t column_of(double x, double y) const;

  using Cell = std::pair<int64_t, int64_t>;  // row along, column across
  struct Run {                               // points of a cell in the spill file
    uint64_t offset = 0, points = 0;         // bytes from the file's start; points
  };
  struct Block {  // points of a cell in memory: x y z steps from the origin
    int32_t* steps = nullptr;
    uint32_t points = 0, capacity = 0;
  };
  struct Held {
    std::vector<Run> spilled;   // the cell's first points, in the file, in order
    std::vector<Block> blocks;  // in memory, after those, in order
    uint64_t points = 0;        // in all
  };

  // Reads the points of columns [col_lo, col_hi] back row by row in order,
  // each row's cells by column. The order must outlive it and take no more
  // points meanwhile.
  class Cursor {
   public:
    Cursor(const AlongTrackOrder& order, int64_t col_lo, int64_t col_hi);
    // Up to max_points points (x y z) into xyz; 0 at the end. Throws
    // std::runtime_error when the temporary file cannot be read.
    size_t read(double* xyz, size_t max_points);

   private:
    const AlongTrackOrder* order_;
    int64_t col_lo_, col_hi_;
    std::map<Cell, Held>::const_iterator cell_;
    std::ifstream file_;   // the spill file, opened at the first run read
    size_t run_ = 0;       // the current cell's next run in the file
    uint64_t in_run_ = 0;  // points of that run already read
    size_t block_ = 0;     // the current cell's block in memory
    uint32_t at_ = 0;      // points of that block already read
    std::vector<int32_t> buf_;
  };

  // The same through a callback, in chunks of at most `chunk` points.
  using ChunkSink = std::function<void(const double* xyz, size_t n)>;
  void replay(int64_t col_lo, int64_t col_hi, size_t chunk, const ChunkSink& on_chunk) const;
  // Every column.
  void replay(size_t chunk, const ChunkSink& on_chunk) const;

 private:
  void new_block(Held& held);
  void spill_all();

  double ax_ = 1.0, ay_ = 0.0;  // the along-track axis
  double row_depth_, column_width_;
  size_t memory_points_;
  size_t held_ = 0;  // points in memory
  uint64_t points_ = 0, nonfinite_ = 0, far_ = 0;
  bool origin_set_ = false;
  double origin_[3] = {0, 0, 0};  // the steps' zero: the first point's metre
  double min_[3], max_[3];
  std::map<Cell, Held> cells_;  // ordered: rows, then columns
  StepSlabs slabs_;             // the blocks' memory
  // Recently used cells, by a hash of the cell (a scan line crosses a few
  // cells and comes back to them): most points find theirs here, not in the map.
  static constexpr size_t kRecentCells = 64;
  struct Recent {
    int64_t row = 0, column = 0;
    Held* held = nullptr;
  };
  Recent recent_[kRecentCells];
  std::filesystem::path dir_;  // made at the first spill
  std::filesystem::path file_path_;
  std::ofstream file_;  // the spill file: cells' runs, appended
  uint64_t file_bytes_ = 0;
};

}  // namespace spinhash::pipeline
