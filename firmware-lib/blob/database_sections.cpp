// Stage 2 of Database::open: the section table. Each entry is checked in
// table order for id, alignment, bounds, overlap and payload CRC, so a bad
// entry is reported before its bytes are read.
#include "blob/database_checks.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace blob_check {
namespace {

bool overlaps(uint64_t a_begin, uint64_t a_size, uint64_t b_begin, uint64_t b_size) {
  return a_begin < b_begin + b_size && b_begin < a_begin + a_size;  // sums checked <= total
}

// Entry against everything accepted so far; on success it is recorded in *s.
Status check_entry(const uint8_t* base, const blob::SectionEntry& e, uint64_t table_end, uint64_t total,
                   Sections* s) {
  if (e.id == 0u || e.id > blob::kSectionIdCount) return Status::kBlobUnknownSection;
  if (s->present[e.id]) return Status::kBlobDuplicateSection;
  if (e.offset % blob::kSectionAlignment != 0u) return Status::kBlobSectionMisaligned;
  if (e.offset > total || e.size > total - e.offset) return Status::kBlobSectionOutOfBounds;
  if (e.offset < table_end) return Status::kBlobSectionOverlap;
  for (uint32_t id = 1; id < kSlotCount; ++id) {
    if (!s->present[id]) continue;
    const uint64_t other = static_cast<uint64_t>(s->data[id] - base);
    if (overlaps(e.offset, e.size, other, s->size[id])) return Status::kBlobSectionOverlap;
  }
  // offset + size <= total == the caller's size_t length, so the casts are exact.
  const uint8_t* payload = base + static_cast<size_t>(e.offset);
  if (crc32c(payload, static_cast<size_t>(e.size)) != e.crc) return Status::kBlobSectionChecksum;
  s->data[e.id] = payload;
  s->size[e.id] = e.size;
  s->present[e.id] = true;
  return Status::kOk;
}

}  // namespace

Status check_sections(const uint8_t* base, Sections* out) {
  const blob::Header& h = *reinterpret_cast<const blob::Header*>(base);
  const blob::SectionEntry* table = reinterpret_cast<const blob::SectionEntry*>(base + sizeof(blob::Header));
  const uint64_t table_end = sizeof(blob::Header) + h.section_count * sizeof(blob::SectionEntry);
  Sections s{};
  for (uint32_t i = 0; i < h.section_count && i < kMaxSections; ++i) {
    const Status st = check_entry(base, table[i], table_end, h.total_size, &s);
    if (st != Status::kOk) return st;
  }
  for (uint32_t id = 1; id < kSlotCount; ++id) {
    if (!s.present[id]) return Status::kBlobMissingSection;
  }
  *out = s;
  return Status::kOk;
}

}  // namespace blob_check
}  // namespace spinhash
