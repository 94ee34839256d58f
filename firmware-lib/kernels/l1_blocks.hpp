// The block order every L1 kernel follows (firmware-lib/kernels/), so that
// each returns the same number as the reference: exact distances, and the
// same partial sum when l1_distance_within stops early.
#pragma once
#include <cstdint>

namespace spinhash {
namespace kernels {

constexpr uint32_t kL1Block = 64;  // bytes summed before the early-exit check: a cache line
constexpr uint32_t kL1Step = 32;   // the first block starts on this step

// Where l1_distance_within looks first (dims >= kL1Block): the last
// kL1Block bytes starting on a kL1Step boundary, the image's upper rows
// (beta from the tangent plane towards the normal). Far images differ most
// there, so a far image exceeds the bound sooner than from byte 0.
inline uint32_t first_block(uint32_t dims) { return (dims - kL1Block) / kL1Step * kL1Step; }

// A kernel's sum of |a[i] - b[i]| over n bytes.
using SadFn = uint32_t (*)(const uint8_t* a, const uint8_t* b, uint32_t n);

// The L1 distance when it is at most `bound`; otherwise the first block's
// sum, which is then above `bound`. Images shorter than a block: exact.
template <SadFn sad>
inline uint32_t within_by_blocks(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  if (dims < kL1Block) return sad(a, b, dims);
  const uint32_t first = first_block(dims);
  const uint32_t head = sad(a + first, b + first, kL1Block);
  if (head > bound) return head;
  const uint32_t rest = first + kL1Block;
  return head + sad(a, b, first) + sad(a + rest, b + rest, dims - rest);
}

constexpr uint32_t kPaperSpinDims = 100;  // the paper's 10 x 10 image (config.hpp's default)

// The optimised kernels give the paper's image size its own copy with
// constant offsets: straight vector code, no loop counters.
template <SadFn sad>
inline uint32_t distance_paper_first(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  return dims == kPaperSpinDims ? sad(a, b, kPaperSpinDims) : sad(a, b, dims);
}
template <SadFn sad>
inline uint32_t within_paper_first(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  if (dims == kPaperSpinDims) return within_by_blocks<sad>(a, b, kPaperSpinDims, bound);
  return within_by_blocks<sad>(a, b, dims, bound);
}

}  // namespace kernels
}  // namespace spinhash
