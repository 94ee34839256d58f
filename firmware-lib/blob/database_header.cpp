// Stage 1 of Database::open: the fixed 64-byte header and the section table's
// extent and checksum. Nothing beyond the header is read before the declared
// size has been matched against the real one.
#include <cstring>

#include "blob/database_checks.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace blob_check {
namespace {

Status check_identity(const blob::Header& h) {
  if (std::memcmp(h.magic, blob::kMagic, sizeof(h.magic)) != 0) return Status::kBlobBadMagic;
  // The mark is checked before any other number, since those would be swapped too.
  if (h.byte_order != blob::kByteOrderMark) {
    return h.byte_order == byteswap32(blob::kByteOrderMark) ? Status::kBlobWrongByteOrder
                                                            : Status::kBlobBadMagic;
  }
  if (h.version != blob::kFormatVersion) return Status::kBlobUnsupportedVersion;
  return Status::kOk;
}

Status check_extent(const blob::Header& h, size_t size) {
  if (h.total_size > size) return Status::kBlobTruncated;
  // Trailing bytes would be unchecked data: refuse them too.
  if (h.total_size < size) return Status::kBlobSizeMismatch;
  if (h.section_count == 0u || h.section_count > kMaxSections) return Status::kBlobCountOverflow;
  const uint64_t table_end =
      sizeof(blob::Header) + static_cast<uint64_t>(h.section_count) * sizeof(blob::SectionEntry);
  if (table_end > h.total_size) return Status::kBlobTruncated;
  return Status::kOk;
}

Status check_header_crc(const uint8_t* base, const blob::Header& h) {
  blob::Header zeroed;
  std::memcpy(&zeroed, &h, sizeof(zeroed));
  zeroed.header_crc = 0u;
  uint32_t crc = crc32c(&zeroed, sizeof(zeroed));
  crc = crc32c(base + sizeof(blob::Header), h.section_count * sizeof(blob::SectionEntry), crc);
  return crc == h.header_crc ? Status::kOk : Status::kBlobHeaderChecksum;
}

}  // namespace

Status check_header(const uint8_t* base, size_t size) {
  if (size < sizeof(blob::Header)) return Status::kBlobTruncated;
  const blob::Header& h = *reinterpret_cast<const blob::Header*>(base);
  Status s = check_identity(h);
  if (s != Status::kOk) return s;
  s = check_extent(h, size);
  if (s != Status::kOk) return s;
  return check_header_crc(base, h);
}

}  // namespace blob_check
}  // namespace spinhash
