// Test helper: a mutable, 64-byte-aligned copy of a native-order blob that a
// test corrupts field by field and then re-seals (CRCs, fingerprint), so the
// check under test, not a checksum, is what rejects it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_content.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace test {

class BlobPatch {
 public:
  explicit BlobPatch(const std::vector<uint8_t>& blob);

  uint8_t* data() { return bytes_.data(); }
  size_t size() const { return bytes_.size(); }
  blob::Header& header();
  blob::SectionEntry& entry(uint32_t index);  // by position in the table
  blob::SectionEntry& entry_of(uint32_t id);  // first entry with this id (must exist)
  uint8_t* payload(uint32_t id);              // section bytes, via the table
  template <typename T>
  T* section(uint32_t id) {
    return reinterpret_cast<T*>(payload(id));
  }
  blob::Params& params() { return *section<blob::Params>(blob::kParams); }
  blob::ModelRecord& model(uint32_t i) { return section<blob::ModelRecord>(blob::kModels)[i]; }

  // Header CRC only (after editing the header or the table).
  void reseal_header();
  // CRC of every in-bounds section, then (optionally) the fingerprint, then the header CRC.
  void reseal(bool fingerprint = true);

  Status open(Database* db = nullptr) const { return open_prefix(size(), db); }
  // Opens only the first `length` bytes (truncation tests).
  Status open_prefix(size_t length, Database* db = nullptr) const;

 private:
  host::AlignedBytes bytes_;
};

// The blob of `content` in native byte order; empty (and a failed CHECK) if refused.
std::vector<uint8_t> write_native(const host::BlobContent& content);

}  // namespace test
}  // namespace spinhash
