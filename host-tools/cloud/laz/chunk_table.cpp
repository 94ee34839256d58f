#include "cloud/laz/chunk_table.hpp"

#include <algorithm>

#include "cloud/cloud_error.hpp"
#include "cloud/laz/integer_decompressor.hpp"

namespace spinhash::host::laz {
namespace {

constexpr uint64_t kOffsetBytes = 8;     // the table's offset before the chunks
constexpr uint64_t kTableHeadBytes = 8;  // version, number of chunks
constexpr uint32_t kTableVersion = 0;
constexpr uint32_t kPointCountContext = 0, kByteCountContext = 1;
constexpr uint64_t kMaxEntryBytes = 16;
constexpr int64_t kOffsetAtEnd = -1;  // the writer put the offset in the last 8 bytes

uint64_t le(const uint8_t* p, int bytes) {
  uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

[[noreturn]] void fail(const std::string& why) { throw CloudError("LAZ: " + why); }

uint64_t table_offset(ByteSource& src, uint64_t points_offset) {
  uint8_t b[kOffsetBytes];
  if (!src.holds(points_offset, kOffsetBytes)) fail("the file ends before the chunk table's offset");
  src.read_at(points_offset, b, kOffsetBytes);
  int64_t at = static_cast<int64_t>(le(b, 8));
  if (at == kOffsetAtEnd || at == 0) {
    if (src.size() < kOffsetBytes) fail("the file ends before the chunk table's offset");
    src.read_at(src.size() - kOffsetBytes, b, kOffsetBytes);
    at = static_cast<int64_t>(le(b, 8));
  }
  const uint64_t first_chunk = points_offset + kOffsetBytes;
  if (at < static_cast<int64_t>(first_chunk) || !src.holds(static_cast<uint64_t>(at), kTableHeadBytes))
    fail("the chunk table's offset " + std::to_string(at) + " lies outside the file's " +
         std::to_string(src.size()) + " bytes (after the point data at " + std::to_string(first_chunk) + ")");
  return static_cast<uint64_t>(at);
}

}  // namespace

std::vector<ChunkEntry> read_chunk_table(ByteSource& src, uint64_t points_offset, const LaszipVlr& vlr,
                                         uint64_t point_count) {
  const uint64_t at = table_offset(src, points_offset);
  uint8_t head[kTableHeadBytes];
  src.read_at(at, head, kTableHeadBytes);
  const uint32_t version = static_cast<uint32_t>(le(head, 4));
  const uint64_t chunks = le(head + 4, 4);
  if (version != kTableVersion) fail("chunk table version " + std::to_string(version) + " is not 0");
  const uint64_t first_chunk = points_offset + kOffsetBytes;
  // Every chunk holds at least one byte: the count is bounded by the bytes.
  if (chunks > at - first_chunk)
    fail("the chunk table lists " + std::to_string(chunks) + " chunks in " +
         std::to_string(at - first_chunk) + " bytes of point data");
  // At most two 32-bit corrections per chunk follow (each at most 5 bytes).
  const uint64_t coded_bytes =
      std::min<uint64_t>(src.size() - at - kTableHeadBytes, chunks * kMaxEntryBytes + 8);
  std::vector<uint8_t> coded(static_cast<size_t>(coded_bytes));
  if (!coded.empty()) src.read_at(at + kTableHeadBytes, coded.data(), coded.size());
  ArithmeticDecoder dec;
  dec.init(coded.data(), coded.data() + coded.size());
  IntegerDecompressor ic(32, 2);
  const bool variable = vlr.chunk_size == kVariableChunkSize;
  std::vector<ChunkEntry> table;
  uint64_t offset = first_chunk, total = 0;
  int32_t last_points = 0, last_bytes = 0;
  for (uint64_t i = 0; i < chunks && total < point_count; ++i) {
    ChunkEntry e;
    if (variable) last_points = ic.decompress(dec, last_points, kPointCountContext);
    last_bytes = ic.decompress(dec, last_bytes, kByteCountContext);
    e.points = variable ? static_cast<uint32_t>(last_points)
                        : std::min<uint64_t>(vlr.chunk_size, point_count - total);
    e.bytes = static_cast<uint32_t>(last_bytes);
    e.offset = offset;
    if (e.points == 0 || e.bytes == 0 || e.bytes > at - offset)
      fail("chunk " + std::to_string(i) + " of the chunk table (" + std::to_string(e.points) + " points, " +
           std::to_string(e.bytes) + " bytes at " + std::to_string(offset) +
           ") does not fit before the table");
    offset += e.bytes;
    total += e.points;
    table.push_back(e);
  }
  if (dec.overrun() > kOffsetBytes) fail("the chunk table is truncated");
  if (total < point_count)
    fail("the chunk table's " + std::to_string(table.size()) + " chunks hold " + std::to_string(total) +
         " points, the header declares " + std::to_string(point_count));
  return table;
}

}  // namespace spinhash::host::laz
