// Internal interface (host tools may use it; not installed, may change):
// the database's quantised form of a spin image and the L1 distance between
// two quantised images, shared by the core, the database builder and the
// experiments so that all three compute the same numbers.
#pragma once
#include <cstdint>

namespace spinhash {

// q = min(255, round(v * scale)): the database's stored form of a spin image.
void quantize_spin(const float* image, uint32_t dims, float scale, uint8_t* out);

namespace detail {

// Sum of |a[i] - b[i]| over n bytes. Called with constant n, it compiles to
// straight vector code (a byte-wise absolute-difference sum).
inline uint32_t l1_bytes(const uint8_t* a, const uint8_t* b, uint32_t n) {
  uint32_t sum = 0;
  for (uint32_t i = 0; i < n; ++i) {
    int32_t d = static_cast<int32_t>(a[i]) - static_cast<int32_t>(b[i]);
    sum += static_cast<uint32_t>(d < 0 ? -d : d);
  }
  return sum;
}

// The bytes [i, dims) after whole 64-byte blocks, in constant blocks of 32
// and 4 bytes: a runtime-length loop over 36 bytes (the 10 x 10 image's
// tail) costs about three times the instructions of these blocks.
inline uint32_t l1_tail(const uint8_t* a, const uint8_t* b, uint32_t i, uint32_t dims) {
  uint32_t sum = 0;
  if (i + 32u <= dims) {
    sum += l1_bytes(a + i, b + i, 32u);
    i += 32u;
  }
  for (; i + 4u <= dims; i += 4u) sum += l1_bytes(a + i, b + i, 4u);
  for (; i < dims; ++i) sum += l1_bytes(a + i, b + i, 1u);
  return sum;
}

constexpr uint32_t kL1Block = 64;  // bytes per early-exit check: a cache line
constexpr uint32_t kL1Step = 32;   // l1_distance_within's first block starts on this step

// Where l1_distance_within looks first (dims >= kL1Block): the last
// kL1Block bytes starting on a kL1Step boundary, the image's upper rows
// (beta from the tangent plane towards the normal). Far images differ most
// there: from byte 0, the 1000-model queries cost 3 % more instructions.
inline uint32_t first_block(uint32_t dims) { return (dims - kL1Block) / kL1Step * kL1Step; }

// Bytes [0, end), end a multiple of kL1Step.
inline uint32_t l1_steps(const uint8_t* a, const uint8_t* b, uint32_t end) {
  uint32_t sum = 0;
  for (uint32_t i = 0; i < end; i += kL1Step) sum += l1_bytes(a + i, b + i, kL1Step);
  return sum;
}

}  // namespace detail

// L1 distance between two quantised spin images (exact integer: the same on every target).
inline uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  uint32_t sum = 0, i = 0;
  for (; i + detail::kL1Block <= dims; i += detail::kL1Block)
    sum += detail::l1_bytes(a + i, b + i, detail::kL1Block);
  return sum + detail::l1_tail(a, b, i, dims);
}

namespace detail {

// l1_distance_within for dims >= kL1Block.
inline uint32_t l1_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  const uint32_t first = first_block(dims);
  const uint32_t sum = l1_bytes(a + first, b + first, kL1Block);
  if (sum > bound) return sum;
  return sum + l1_steps(a, b, first) + l1_tail(a, b, first + kL1Block, dims);
}

constexpr uint32_t kPaperSpinDims = 100;  // the paper's 10 x 10 image (config.hpp's default)

}  // namespace detail

// The L1 distance when it is at most `bound`; otherwise some partial sum
// above `bound` (the scan stops there: most database entries a query
// feature is compared with are far beyond the candidates it keeps). The
// paper's image size gets its own copy with constant offsets: straight
// vector code (3 % fewer instructions per query at 1000 models).
inline uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  if (dims == detail::kPaperSpinDims) return detail::l1_within(a, b, detail::kPaperSpinDims, bound);
  if (dims < detail::kL1Block) return detail::l1_tail(a, b, 0u, dims);
  return detail::l1_within(a, b, dims, bound);
}

}  // namespace spinhash
