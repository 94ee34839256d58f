// Stage 3b of Database::open (after the Params stage sized the Params and
// model sections, before the model stage): every byte that carries no value is zero, so
// that no single-byte change of a blob goes unnoticed. The CRCs cover the
// header, the table and the payloads; this covers the padding between them
// (no CRC) and the reserved fields and name tails (covered, but a writer
// that put something there would be relying on a meaning the format has not
// given them yet).
#include "blob/database_checks.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace blob_check {
namespace {

// The bytes after a name's NUL (a name without one is check_models' to refuse).
bool name_tail_zero(const char* name) {
  uint32_t k = 0;
  while (k < kMaxModelNameBytes && name[k] != '\0') ++k;
  for (; k < kMaxModelNameBytes; ++k)
    if (name[k] != '\0') return false;
  return true;
}

bool reserved_fields_zero(const uint8_t* base, const Sections& s) {
  const blob::Header& h = *reinterpret_cast<const blob::Header*>(base);
  if (!all_zero(h.reserved, sizeof(h.reserved))) return false;
  const blob::SectionEntry* table = reinterpret_cast<const blob::SectionEntry*>(base + sizeof(blob::Header));
  for (uint32_t i = 0; i < h.section_count && i < kMaxSections; ++i)
    if (table[i].reserved != 0u || table[i].reserved2 != 0u) return false;
  const blob::Params& p = params_of(s);
  if (!all_zero(p.reserved, sizeof(p.reserved))) return false;
  const blob::ModelRecord* models = section_as<blob::ModelRecord>(s, blob::kModels);
  for (uint32_t m = 0; m < p.model_count && m < kMaxModels; ++m) {
    if (!all_zero(models[m].reserved, sizeof(models[m].reserved)) || !name_tail_zero(models[m].name))
      return false;
  }
  return true;
}

// The payloads' [begin, end) in blob order (insertion sort of eleven).
uint32_t payloads_in_order(const uint8_t* base, const Sections& s, uint64_t* begin, uint64_t* end) {
  uint32_t n = 0;
  for (uint32_t id = 1; id < kSlotCount; ++id) {
    const uint64_t b = static_cast<uint64_t>(s.data[id] - base), e = b + s.size[id];
    uint32_t j = n++;
    for (; j > 0 && begin[j - 1u] > b; --j) begin[j] = begin[j - 1u], end[j] = end[j - 1u];
    begin[j] = b, end[j] = e;
  }
  return n;
}

// The gaps between the table and the first payload, between payloads and after the last.
bool padding_zero(const uint8_t* base, const Sections& s) {
  const blob::Header& h = *reinterpret_cast<const blob::Header*>(base);
  uint64_t begin[kSlotCount], end[kSlotCount];
  const uint32_t n = payloads_in_order(base, s, begin, end);
  uint64_t cursor =
      sizeof(blob::Header) + static_cast<uint64_t>(h.section_count) * sizeof(blob::SectionEntry);
  for (uint32_t i = 0; i < n; ++i) {
    if (begin[i] > cursor && !all_zero(base + cursor, begin[i] - cursor)) return false;
    cursor = end[i] > cursor ? end[i] : cursor;
  }
  return all_zero(base + cursor, h.total_size - cursor);
}

}  // namespace

Status check_zero_fill(const uint8_t* base, const Sections& s) {
  if (!reserved_fields_zero(base, s) || !padding_zero(base, s)) return Status::kBlobNotZeroed;
  return Status::kOk;
}

}  // namespace blob_check
}  // namespace spinhash
