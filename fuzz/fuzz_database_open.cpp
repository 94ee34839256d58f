// Database::open on arbitrary bytes: it must refuse or accept without reading
// outside the buffer, and whatever it accepts the recognizer must then run on
// without a fault ("validate once, then trust"). Input: one flags byte, then
// the blob. Flag bit 0 re-seals the checksums and fingerprint first, so that
// mutations get past the CRCs and reach the structural checks behind them.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_support.hpp"
#include "spinhash/blob_format.hpp"
#include "spinhash/database.hpp"
#include "spinhash/limits.hpp"

using namespace spinhash;

namespace {

constexpr uint8_t kFlagReseal = 1u;

// Mirrors tests/support/blob_patch.cpp: every in-bounds section CRC, the
// params fingerprint, then the header CRC over header + table.
void reseal(uint8_t* data, size_t size) {
  if (size < sizeof(blob::Header)) return;
  blob::Header h;
  std::memcpy(&h, data, sizeof h);
  const uint32_t count = h.section_count < kMaxSections ? h.section_count : kMaxSections;
  for (uint32_t i = 0; i < count; ++i) {
    const size_t at = sizeof(blob::Header) + i * sizeof(blob::SectionEntry);
    if (at + sizeof(blob::SectionEntry) > size) break;
    blob::SectionEntry e;
    std::memcpy(&e, data + at, sizeof e);
    if (e.offset > size || e.size > size - e.offset) continue;
    e.crc = crc32c(data + e.offset, static_cast<size_t>(e.size));
    if (e.id == blob::kParams && e.size >= sizeof(blob::Params))
      h.config_fingerprint = fnv1a64(data + e.offset, sizeof(blob::Params));
    std::memcpy(data + at, &e, sizeof e);
  }
  h.header_crc = 0;
  std::memcpy(data, &h, sizeof h);
  const size_t table = static_cast<size_t>(h.section_count) * sizeof(blob::SectionEntry);
  const size_t covered =
      h.section_count <= kMaxSections && sizeof h + table <= size ? sizeof h + table : sizeof h;
  h.header_crc = crc32c(data, covered);
  std::memcpy(data, &h, sizeof h);
}

// A fixed query: four squares of points (three orthogonal, one raised), enough for features.
const std::vector<float>& query_points() {
  static const std::vector<float> points = [] {
    std::vector<float> p;
    constexpr int kSide = 12;       // 4 * 144 points: the blob, not feature extraction, is under test
    constexpr float kStep = 0.15f;  // m
    for (int i = 0; i < kSide; ++i)
      for (int j = 0; j < kSide; ++j) {
        const float a = i * kStep, b = j * kStep;
        for (float v : {a, b, 0.0f, a, 0.0f, b, 0.0f, a, b, a, b, 1.5f}) p.push_back(v);
      }
    return p;
  }();
  return points;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t flags = data[0];
  host::AlignedBytes blob = host::AlignedBytes::copy_of(data + 1, size - 1);
  if (flags & kFlagReseal) reseal(blob.data(), blob.size());
  Database db;
  if (Database::open(blob.data(), blob.size(), &db) != Status::kOk) {
    fuzz::require(!db.is_open(), "failed open left the view open");
    return 0;
  }
  // Accepted: every accessor and a whole recognition must stay in bounds.
  fuzz::require(db.find_model(db.model(0).name) >= 0, "first model not found by name");
  static fuzz::Session session;
  if (session.init(&db, fuzz::small_config(Mode::kBran)) != Status::kOk) return 0;
  const std::vector<float>& q = query_points();
  const uint32_t n = static_cast<uint32_t>(q.size() / 3);
  fuzz::check_result(session.recognizer.recognize(q.data(), n), db, n, session.workspace.size());
  return 0;
}
