// The LASzip VLR (user id "laszip encoded", record 22204): which compressor
// and coder, the chunk size, and the items a point is made of. Parsing
// checks every field against what this decoder takes and names what is
// wrong.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host::laz {

constexpr const char* kLaszipUserId = "laszip encoded";
constexpr uint16_t kLaszipRecordId = 22204;

enum class Compressor : uint16_t { kNone = 0, kPointwise = 1, kPointwiseChunked = 2, kLayeredChunked = 3 };
constexpr uint16_t kArithmeticCoder = 0;
// Extra bytes decoded per point at most (real files carry tens): each byte
// costs a model per scanner channel.
constexpr uint16_t kMaxLazExtraBytes = 1024;
constexpr uint32_t kVariableChunkSize = 0xFFFFFFFFu;  // chunk sizes in the chunk table

enum class ItemType : uint16_t {
  kByte = 0,
  kShort = 1,
  kInt = 2,
  kLong = 3,
  kFloat = 4,
  kDouble = 5,
  kPoint10 = 6,
  kGpsTime11 = 7,
  kRgb12 = 8,
  kWavepacket13 = 9,
  kPoint14 = 10,
  kRgb14 = 11,
  kRgbNir14 = 12,
  kWavepacket14 = 13,
  kByte14 = 14,
};

struct LazItem {
  ItemType type;
  uint16_t size;
  uint16_t version;
};

struct LaszipVlr {
  Compressor compressor = Compressor::kNone;
  uint16_t coder = 0;
  uint8_t version_major = 0, version_minor = 0;
  uint16_t version_revision = 0;
  uint32_t options = 0;
  uint32_t chunk_size = 0;
  std::vector<LazItem> items;

  bool layered() const { return compressor == Compressor::kLayeredChunked; }
  bool chunked() const { return compressor != Compressor::kPointwise; }
};

// "POINT10", "GPSTIME11", ... or "type N".
std::string item_name(ItemType type);

// Parses and checks the VLR's payload against the point record it must
// describe. Throws CloudError ("LAZ: ...") naming the field that is wrong.
LaszipVlr parse_laszip_vlr(const uint8_t* data, size_t size, uint8_t point_format, uint16_t record_length);

}  // namespace spinhash::host::laz
