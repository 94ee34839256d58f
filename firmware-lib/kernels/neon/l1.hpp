// NEON L1 kernels (aarch64; armhf built with -mfpu=neon): vabdq_u8 takes the
// absolute differences of 16 byte pairs, vpadalq_u8 adds their pairs into
// eight 16-bit lanes.
#pragma once
#if defined(__ARM_NEON)
#include <arm_neon.h>

#include <cstdint>
#include <cstring>

#include "kernels/l1_blocks.hpp"
#include "kernels/reference/l1.hpp"

#define SPINHASH_KERNELS_HAVE_NEON 1

namespace spinhash {
namespace kernels {
namespace neon {

constexpr const char* kName = "neon";

// A 16-bit lane gains at most 2 * 255 per 16 bytes (and 255 for a last 8):
// it is summed out after at most this many bytes, long before 65 535.
constexpr uint32_t kLaneFlushBytes = 1024;

inline uint32_t horizontal_sum(uint16x8_t acc) {
#if defined(__aarch64__)
  return vaddlvq_u16(acc);
#else
  const uint64x2_t halves = vpaddlq_u32(vpaddlq_u16(acc));
  return static_cast<uint32_t>(vgetq_lane_u64(halves, 0) + vgetq_lane_u64(halves, 1));
#endif
}

// 4 bytes in the low lanes, zeros above (never a load past the image's end).
inline uint8x8_t load4(const uint8_t* p) {
  uint32_t v;
  std::memcpy(&v, p, sizeof v);
  return vreinterpret_u8_u32(vset_lane_u32(v, vdup_n_u32(0), 0));
}

// Bytes [0, end) in 16-byte steps, end a multiple of 16 and at most kLaneFlushBytes.
inline uint16x8_t sad16(const uint8_t* a, const uint8_t* b, uint32_t end) {
  uint16x8_t acc = vdupq_n_u16(0);
  for (uint32_t i = 0; i < end; i += 16u) acc = vpadalq_u8(acc, vabdq_u8(vld1q_u8(a + i), vld1q_u8(b + i)));
  return acc;
}

inline uint32_t sad(const uint8_t* a, const uint8_t* b, uint32_t n) {
  uint32_t sum = 0, i = 0;
  while (n - i >= 16u) {
    const uint32_t left = (n - i) / 16u * 16u;
    const uint32_t chunk = left < kLaneFlushBytes ? left : kLaneFlushBytes;
    sum += horizontal_sum(sad16(a + i, b + i, chunk));
    i += chunk;
  }
  if (n - i >= 8u) {
    sum += horizontal_sum(vabdl_u8(vld1_u8(a + i), vld1_u8(b + i)));
    i += 8u;
  }
  if (n - i >= 4u) {  // the paper's 100-byte image ends in 4 bytes
    sum += horizontal_sum(vabdl_u8(load4(a + i), load4(b + i)));
    i += 4u;
  }
  return sum + reference::sad(a + i, b + i, n - i);
}

inline uint32_t l1_distance(const uint8_t* a, const uint8_t* b, uint32_t dims) {
  return distance_paper_first<sad>(a, b, dims);
}

inline uint32_t l1_distance_within(const uint8_t* a, const uint8_t* b, uint32_t dims, uint32_t bound) {
  return within_paper_first<sad>(a, b, dims, bound);
}

}  // namespace neon
}  // namespace kernels
}  // namespace spinhash
#endif  // __ARM_NEON
