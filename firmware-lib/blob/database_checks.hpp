// Internal stages of Database::open. Each stage may assume that every stage
// before it succeeded (that is what makes the later reads safe), and returns
// the first failure it finds. Order: header -> sections -> params -> zero
// fill -> models -> features -> lsh -> calibration.
#pragma once
#include <cstddef>
#include <cstdint>

#include "spinhash/blob_format.hpp"
#include "spinhash/status.hpp"

namespace spinhash {
namespace blob_check {

// The field offsets docs/blob-format.md promises; a compiler that pads
// differently must fail here rather than misread blobs.
static_assert(offsetof(blob::Header, total_size) == 16 && offsetof(blob::Header, section_count) == 32 &&
                  offsetof(blob::Header, header_crc) == 36,
              "header layout");
static_assert(offsetof(blob::SectionEntry, offset) == 8 && offsetof(blob::SectionEntry, crc) == 24,
              "section entry layout");
static_assert(offsetof(blob::Params, cloud_voxel) == 32 && offsetof(blob::Params, field_entry_count) == 64 &&
                  offsetof(blob::Params, reserved) == 80,
              "params layout");
static_assert(offsetof(blob::CalibrationHeader, band_min_density) == 16 &&
                  offsetof(blob::CalibrationHeader, scans_per_model) == 80 &&
                  offsetof(blob::CalibrationHeader, seed) == 96 &&
                  offsetof(blob::CalibrationHeader, clutter) == 104 &&
                  offsetof(blob::CalibrationHeader, reserved) == 108,
              "calibration header layout");
static_assert(offsetof(blob::CalibrationCell, positives) == 12 &&
                  offsetof(blob::CalibrationCell, state) == 24,
              "calibration cell layout");
static_assert(offsetof(blob::ModelRecord, first_feature) == 48 &&
                  offsetof(blob::ModelRecord, grid_offset_base) == 68 &&
                  offsetof(blob::ModelRecord, bbox_max) == 96 &&
                  offsetof(blob::ModelRecord, field_dims) == 108 &&
                  offsetof(blob::ModelRecord, vehicle_class) == 124 &&
                  offsetof(blob::ModelRecord, vehicle_group) == 125 &&
                  offsetof(blob::ModelRecord, reserved) == 126,
              "model record layout");

constexpr uint32_t kSlotCount = blob::kSectionIdCount + 1;  // indexed by SectionId; slot 0 unused

// Payload of every section, located and checksummed by check_sections.
struct Sections {
  const uint8_t* data[kSlotCount];
  uint64_t size[kSlotCount];
  bool present[kSlotCount];
};

template <typename T>
inline const T* section_as(const Sections& s, uint32_t id) {
  // Offsets are multiples of 64 from a 64-aligned base, so T is aligned.
  return reinterpret_cast<const T*>(s.data[id]);
}

inline const blob::Params& params_of(const Sections& s) {
  return *section_as<blob::Params>(s, blob::kParams);
}

// Header fields, total size, section table bounds and the header CRC.
Status check_header(const uint8_t* base, size_t size);
// Every table entry (id, alignment, bounds, overlap, CRC) and presence of all ids.
Status check_sections(const uint8_t* base, Sections* out);
// Params size, counts, section sizes, float ranges, config fingerprint.
Status check_params(const blob::Header& header, const Sections& s);
// Padding, reserved fields and name tails: zero (after check_params, which sizes
// the Params and model sections).
Status check_zero_fill(const uint8_t* base, const Sections& s);
// Model records: names, feature ranges, grids and their offsets, fields and their slots.
Status check_models(const Sections& s);
// Per-feature positions, normals and model ids.
Status check_features(const Sections& s);
// LSH bits, per-table bucket offsets and entries.
Status check_lsh(const Sections& s);
// The Calibration section: counts and size, density bands, passes, cells.
Status check_calibration(const Sections& s);

// No bit set in n bytes.
inline bool all_zero(const uint8_t* p, uint64_t n) {
  uint8_t any = 0;
  for (uint64_t i = 0; i < n; ++i) any |= p[i];
  return any == 0u;
}

// a * b into *out unless it overflows 64 bits.
inline bool mul_u64(uint64_t a, uint64_t b, uint64_t* out) {
  if (a != 0u && b > UINT64_MAX / a) return false;
  *out = a * b;
  return true;
}

inline uint32_t byteswap32(uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0x0000FF00u) | ((v << 8) & 0x00FF0000u) | (v << 24);
}

}  // namespace blob_check
}  // namespace spinhash
