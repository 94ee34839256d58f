#include "cloud/laz/laszip_vlr.hpp"

#include "cloud/cloud_error.hpp"

namespace spinhash::host::laz {
namespace {

// Byte offsets in the VLR payload (LAZ specification, "LASzip VLR").
constexpr size_t kCompressorAt = 0, kCoderAt = 2, kVersionMajorAt = 4, kVersionMinorAt = 5;
constexpr size_t kRevisionAt = 6, kOptionsAt = 8, kChunkSizeAt = 12, kItemCountAt = 32, kItemsAt = 34;
constexpr size_t kItemBytes = 6;
constexpr uint8_t kFirstFormat14 = 6;  // formats 6-10 use the POINT14 items
constexpr uint8_t kMaxLazFormat = 10;

uint32_t le(const uint8_t* p, int bytes) {
  uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

[[noreturn]] void fail(const std::string& why) { throw CloudError("LAZ: " + why); }

// The size an item must have (0: any size, the extra bytes).
uint16_t required_size(ItemType t) {
  switch (t) {
    case ItemType::kPoint10: return 20;
    case ItemType::kGpsTime11: return 8;
    case ItemType::kRgb12: return 6;
    case ItemType::kWavepacket13: return 29;
    case ItemType::kPoint14: return 30;
    case ItemType::kRgb14: return 6;
    case ItemType::kRgbNir14: return 8;
    case ItemType::kWavepacket14: return 29;
    default: return 0;
  }
}

bool pointwise_item(ItemType t) {
  return t == ItemType::kPoint10 || t == ItemType::kGpsTime11 || t == ItemType::kRgb12 ||
         t == ItemType::kByte;
}
bool layered_item(ItemType t) {
  return t == ItemType::kPoint14 || t == ItemType::kRgb14 || t == ItemType::kRgbNir14 ||
         t == ItemType::kByte14;
}

void check_item(const LazItem& item, size_t index, bool layered) {
  const std::string what = "item " + std::to_string(index + 1) + " (" + item_name(item.type) + ")";
  const uint16_t t = static_cast<uint16_t>(item.type);
  if (t > static_cast<uint16_t>(ItemType::kByte14))
    fail("item " + std::to_string(index + 1) + " has type " + std::to_string(t) +
         ", which is no LASzip item type");
  if (item.type == ItemType::kWavepacket13 || item.type == ItemType::kWavepacket14)
    fail(what + ": waveform packets are not decoded by this reader");
  if (!pointwise_item(item.type) && !layered_item(item.type))
    fail(what + ": LASzip does not compress this item type");
  const uint16_t size = required_size(item.type);
  if ((size != 0 && item.size != size) || item.size == 0)
    fail(what + " has size " + std::to_string(item.size) + ", it must be " +
         (size != 0 ? std::to_string(size) : std::string("at least 1")));
  if ((item.type == ItemType::kByte || item.type == ItemType::kByte14) && item.size > kMaxLazExtraBytes)
    fail(what + " carries " + std::to_string(item.size) +
         " extra bytes per point; this reader decodes at most " + std::to_string(kMaxLazExtraBytes));
  if (layered != layered_item(item.type))
    fail(what + " cannot be in a " + (layered ? "layered (compressor 3)" : "pointwise (compressor 1 or 2)") +
         " point");
  const bool ok =
      layered ? (item.version == 3 || item.version == 4) : (item.version == 1 || item.version == 2);
  if (!ok)
    fail(what + " has version " + std::to_string(item.version) + "; this reader decodes versions " +
         (layered ? "3 and 4" : "1 and 2"));
}

}  // namespace

std::string item_name(ItemType type) {
  static const char* const kNames[] = {"BYTE",    "SHORT",   "INT",       "LONG",         "FLOAT",
                                       "DOUBLE",  "POINT10", "GPSTIME11", "RGB12",        "WAVEPACKET13",
                                       "POINT14", "RGB14",   "RGBNIR14",  "WAVEPACKET14", "BYTE14"};
  const uint16_t t = static_cast<uint16_t>(type);
  return t < sizeof kNames / sizeof kNames[0] ? kNames[t] : "type " + std::to_string(t);
}

LaszipVlr parse_laszip_vlr(const uint8_t* d, size_t size, uint8_t point_format, uint16_t record_length) {
  if (size < kItemsAt)
    fail("the LASzip VLR holds " + std::to_string(size) + " bytes, fewer than its 34-byte head");
  LaszipVlr v;
  const uint16_t compressor = static_cast<uint16_t>(le(d + kCompressorAt, 2));
  v.coder = static_cast<uint16_t>(le(d + kCoderAt, 2));
  v.version_major = d[kVersionMajorAt];
  v.version_minor = d[kVersionMinorAt];
  v.version_revision = static_cast<uint16_t>(le(d + kRevisionAt, 2));
  v.options = le(d + kOptionsAt, 4);
  v.chunk_size = le(d + kChunkSizeAt, 4);
  const size_t count = le(d + kItemCountAt, 2);
  if (v.coder != kArithmeticCoder)
    fail("the LASzip VLR names coder " + std::to_string(v.coder) +
         "; the only LASzip coder is 0 (arithmetic)");
  if (compressor < 1 || compressor > 3)
    fail("the LASzip VLR names compressor " + std::to_string(compressor) +
         "; LASzip compressors are 1 (pointwise), 2 (pointwise chunked) and 3 (layered chunked)");
  v.compressor = static_cast<Compressor>(compressor);
  if (v.chunked() && v.chunk_size == 0) fail("the LASzip VLR declares chunks of 0 points");
  if (size < kItemsAt + count * kItemBytes)
    fail("the LASzip VLR lists " + std::to_string(count) + " items but holds bytes for " +
         std::to_string((size - kItemsAt) / kItemBytes));
  if (count == 0) fail("the LASzip VLR lists no items");
  uint32_t total = 0;
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* p = d + kItemsAt + i * kItemBytes;
    const LazItem item{static_cast<ItemType>(le(p, 2)), static_cast<uint16_t>(le(p + 2, 2)),
                       static_cast<uint16_t>(le(p + 4, 2))};
    check_item(item, i, v.layered());
    total += item.size;
    v.items.push_back(item);
  }
  const ItemType first = v.items.front().type;
  const bool format14 = point_format >= kFirstFormat14;
  if (point_format > kMaxLazFormat)
    fail("point data format " + std::to_string(point_format) + " is not 0-10");
  if (format14 != (first == ItemType::kPoint14) || (!format14 && first != ItemType::kPoint10))
    fail("point format " + std::to_string(point_format) + " cannot start with item " + item_name(first));
  if (total != record_length)
    fail("the LASzip items hold " + std::to_string(total) +
         " bytes per point, the header's record length is " + std::to_string(record_length));
  return v;
}

}  // namespace spinhash::host::laz
