#include "blob/blob_layout.hpp"

namespace spinhash {
namespace host {
namespace {

struct Expected {
  uint32_t id;
  const char* name;
  uint64_t elements;  // what the params call for
  uint64_t actual;    // what the vector holds
  uint64_t element_bytes;
};

uint64_t align_up(uint64_t v, uint64_t a) { return (v + a - 1u) / a * a; }

}  // namespace

bool plan_blob_layout(const BlobContent& c, BlobLayout* layout, std::string* error) {
  const blob::Params& p = c.params;
  // Counts are uint32, so every product below fits in 64 bits.
  const uint64_t n = p.feature_count;
  const uint64_t dims = static_cast<uint64_t>(p.bins_alpha) * p.bins_beta;
  const uint64_t tables = p.lsh_tables;
  // The calibration's size follows from its own header: what the vectors hold, counted alike.
  blob::CalibrationHeader held = c.calibration.header;
  held.pass_count = static_cast<uint32_t>(c.calibration.passes.size());
  held.band_count =
      held.pass_count * held.level_count == 0u
          ? 0u
          : static_cast<uint32_t>(c.calibration.cells.size() / (held.pass_count * held.level_count));
  if (static_cast<uint64_t>(held.pass_count) * held.level_count * held.band_count !=
      c.calibration.cells.size()) {
    *error = "calibration holds " + std::to_string(c.calibration.cells.size()) +
             " cells, not a whole table per pass";
    return false;
  }
  const Expected expected[blob::kSectionIdCount] = {
      {blob::kParams, "params", 1u, 1u, sizeof(blob::Params)},
      {blob::kModels, "models", p.model_count, c.models.size(), sizeof(blob::ModelRecord)},
      {blob::kFeatPositions, "positions", 3u * n, c.positions.size(), sizeof(float)},
      {blob::kFeatNormals, "normals", 3u * n, c.normals.size(), sizeof(int16_t)},
      {blob::kFeatModels, "feature_models", n, c.feature_models.size(), sizeof(uint16_t)},
      {blob::kFeatSpins, "spins", dims * n, c.spins.size(), 1u},
      {blob::kGridOffsets, "grid_offsets", p.grid_offset_count, c.grid_offsets.size(), sizeof(uint32_t)},
      {blob::kLshBits, "lsh_bits", tables * p.lsh_bits, c.lsh_bits.size(), sizeof(blob::LshBit)},
      {blob::kLshOffsets, "lsh_offsets", tables * (static_cast<uint64_t>(p.lsh_buckets) + 1u),
       c.lsh_offsets.size(), sizeof(uint32_t)},
      {blob::kLshEntries, "lsh_entries", tables * n, c.lsh_entries.size(), sizeof(uint32_t)},
      {blob::kNearestField, "nearest_field", p.field_entry_count, c.nearest_field.size(), sizeof(uint16_t)},
      {blob::kCalibration, "calibration", calibration_bytes(c.calibration.header), calibration_bytes(held),
       1u},
  };
  uint64_t end = sizeof(blob::Header) + blob::kSectionIdCount * sizeof(blob::SectionEntry);
  for (uint32_t i = 0; i < blob::kSectionIdCount; ++i) {
    const Expected& e = expected[i];
    if (e.elements != e.actual) {
      *error = std::string(e.name) + " holds " + std::to_string(e.actual) + " elements, params call for " +
               std::to_string(e.elements);
      return false;
    }
    const uint64_t offset = align_up(end, blob::kSectionAlignment);
    layout->sections[i] = {e.id, offset, e.elements * e.element_bytes};
    end = offset + layout->sections[i].size;
  }
  layout->total_size = end;
  return true;
}

}  // namespace host
}  // namespace spinhash
