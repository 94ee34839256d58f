// CRC-32C (Castagnoli) and FNV-1a 64, the two checksums of the blob format.
// Byte-at-a-time table lookup: simple, endian-neutral, fast enough for a
// one-off validation of a blob at open time.
#include <cstddef>
#include <cstdint>

#include "spinhash/database.hpp"
#include "spinhash/internal/fnv1a.hpp"

namespace spinhash {
namespace {

constexpr uint32_t kCrc32cReflectedPoly = 0x82F63B78u;  // 0x1EDC6F41 bit-reversed
constexpr uint32_t kCrcTableSize = 256;
constexpr uint32_t kBitsPerByte = 8;
constexpr uint64_t kFnvPrime = 0x00000100000001B3ull;

struct CrcTable {
  uint32_t entry[kCrcTableSize];
};

constexpr CrcTable make_crc_table() {
  CrcTable t{};
  for (uint32_t i = 0; i < kCrcTableSize; ++i) {
    uint32_t c = i;
    for (uint32_t b = 0; b < kBitsPerByte; ++b) {
      c = (c & 1u) != 0u ? (c >> 1) ^ kCrc32cReflectedPoly : c >> 1;
    }
    t.entry[i] = c;
  }
  return t;
}

// Generated at compile time, lives in .rodata (flash on a microcontroller).
constexpr CrcTable kCrcTable = make_crc_table();
static_assert(kCrcTable.entry[1] == 0xF26B8303u, "CRC-32C table");

}  // namespace

uint32_t crc32c(const void* data, size_t size, uint32_t crc) noexcept {
  const uint8_t* p = static_cast<const uint8_t*>(data);
  uint32_t c = ~crc;  // continue from a previous (finalised) value; 0 starts afresh
  for (size_t i = 0; i < size; ++i) {
    c = kCrcTable.entry[(c ^ p[i]) & 0xFFu] ^ (c >> kBitsPerByte);
  }
  return ~c;
}

uint64_t fnv1a64_update(uint64_t h, const void* data, size_t size) noexcept {
  const uint8_t* p = static_cast<const uint8_t*>(data);
  for (size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= kFnvPrime;
  }
  return h;
}

uint64_t fnv1a64(const void* data, size_t size) noexcept { return fnv1a64_update(kFnv1a64Basis, data, size); }

}  // namespace spinhash
