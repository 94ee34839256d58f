// Blocks of 32-bit steps for the along-track order (tile_stream_order.hpp),
// carved from large slabs: a cell's points grow block by block (never
// copied, as a growing vector would), and the slabs are kept for reuse when
// the order spills, so their pages are touched once. The slabs ask the
// kernel for huge pages (madvise): a dense tile's points cost a few page
// faults, not one per 4 kB.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace spinhash::pipeline {

class StepSlabs {
 public:
  // A block of `ints` int32 (at most kSlabInts); throws std::bad_alloc.
  int32_t* alloc(size_t ints);
  // Every block is free again; the slabs stay for the next blocks.
  void clear();

  // Bytes per slab: a multiple of the 2 MB huge page.
  static constexpr size_t kSlabBytes = size_t{32} << 20;
  static constexpr size_t kSlabInts = kSlabBytes / sizeof(int32_t);

 private:
  struct FreeSlab {
    void operator()(int32_t* p) const;
  };
  std::vector<std::unique_ptr<int32_t, FreeSlab>> slabs_;
  size_t slab_ = 0;  // the slab blocks are carved from
  size_t used_ = 0;  // ints of it carved
};

}  // namespace spinhash::pipeline
