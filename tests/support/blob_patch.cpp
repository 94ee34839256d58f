#include "support/blob_patch.hpp"

#include <doctest/doctest.h>

#include <string>

#include "blob/blob_writer.hpp"

namespace spinhash {
namespace test {

BlobPatch::BlobPatch(const std::vector<uint8_t>& blob) : bytes_(host::AlignedBytes::copy_of(blob)) {}

blob::Header& BlobPatch::header() { return *reinterpret_cast<blob::Header*>(data()); }

blob::SectionEntry& BlobPatch::entry(uint32_t index) {
  REQUIRE(sizeof(blob::Header) + (index + 1u) * sizeof(blob::SectionEntry) <= size());
  return reinterpret_cast<blob::SectionEntry*>(data() + sizeof(blob::Header))[index];
}

blob::SectionEntry& BlobPatch::entry_of(uint32_t id) {
  for (uint32_t i = 0; i < header().section_count && i < kMaxSections; ++i) {
    if (entry(i).id == id) return entry(i);
  }
  FAIL("no section with id " << id);
  return entry(0);
}

uint8_t* BlobPatch::payload(uint32_t id) {
  const blob::SectionEntry& e = entry_of(id);
  REQUIRE(e.offset + e.size <= size());
  return data() + e.offset;
}

void BlobPatch::reseal_header() {
  blob::Header& h = header();
  h.header_crc = 0u;
  const size_t table = h.section_count * sizeof(blob::SectionEntry);
  const size_t covered =
      sizeof(blob::Header) + table <= size() ? sizeof(blob::Header) + table : sizeof(blob::Header);
  h.header_crc = crc32c(data(), covered);
}

void BlobPatch::reseal(bool fingerprint) {
  const uint32_t count = header().section_count;
  for (uint32_t i = 0; i < count && i < kMaxSections; ++i) {
    blob::SectionEntry& e = entry(i);
    if (e.offset > size() || e.size > size() - e.offset) continue;  // nothing to checksum
    e.crc = crc32c(data() + e.offset, static_cast<size_t>(e.size));
    if (fingerprint && e.id == blob::kParams && e.size >= sizeof(blob::Params)) {
      header().config_fingerprint = fnv1a64(data() + e.offset, sizeof(blob::Params));
    }
  }
  reseal_header();
}

Status BlobPatch::open_prefix(size_t length, Database* db) const {
  Database scratch;
  return Database::open(bytes_.data(), length, db != nullptr ? db : &scratch);
}

std::vector<uint8_t> write_native(const host::BlobContent& content) {
  std::vector<uint8_t> bytes;
  std::string error;
  const bool ok = host::serialize_blob(content, host::ByteOrder::kNative, &bytes, &error);
  CHECK_MESSAGE(ok, error);
  return bytes;
}

}  // namespace test
}  // namespace spinhash
