// Stage 4 of Database::open: the model table. Models own consecutive,
// non-empty feature ranges that tile [0, feature_count), and consecutive,
// non-overlapping grid-offset and nearest-field ranges, so this stage (and every later per-model
// loop) costs time proportional to the blob size.
#include <cmath>

#include "blob/database_checks.hpp"
#include "spinhash/database.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash {
namespace blob_check {
namespace {

bool name_ok(const char (&name)[kMaxModelNameBytes]) {
  if (name[0] == '\0') return false;
  for (uint32_t k = 1; k < kMaxModelNameBytes; ++k) {
    if (name[k] == '\0') return true;
  }
  return false;
}

bool all_finite(const float* v, uint32_t n) {
  for (uint32_t k = 0; k < n; ++k) {
    if (!std::isfinite(v[k])) return false;
  }
  return true;
}

bool geometry_ok(const blob::ModelRecord& m) {
  if (!all_finite(m.grid_origin, 3u) || !all_finite(m.bbox_min, 3u) || !all_finite(m.bbox_max, 3u)) {
    return false;
  }
  for (uint32_t k = 0; k < 3u; ++k) {
    if (m.bbox_min[k] > m.bbox_max[k]) return false;
  }
  return true;
}

// Product of three dimensions, or 0 if one is 0 or the product exceeds
// limit (<= 2^24: each partial product stays below 2^48, no overflow).
static_assert(kMaxGridCellsPerModel <= (1u << 24) && kMaxFieldVoxelsPerModel <= (1u << 24),
              "bounded_volume's products fit in 64 bits");
uint64_t bounded_volume(const uint32_t (&dims)[3], uint32_t limit) {
  uint64_t volume = 1;
  for (uint32_t k = 0; k < 3u; ++k) {
    if (dims[k] == 0u || dims[k] > limit) return 0u;
    volume *= dims[k];
    if (volume > limit) return 0u;
  }
  return volume;
}

// Cells of the model's grid, or 0 if a dimension is 0 or the product is too large.
uint64_t grid_cells(const blob::ModelRecord& m) { return bounded_volume(m.grid_dims, kMaxGridCellsPerModel); }

// Offsets of one model: start at 0, never decrease, end at its feature count.
bool grid_offsets_ok(const uint32_t* off, uint64_t cells, uint32_t feature_count) {
  if (off[0] != 0u || off[cells] != feature_count) return false;
  for (uint64_t c = 0; c < cells; ++c) {
    if (off[c + 1u] < off[c]) return false;
  }
  return true;
}

// Voxels of the model's nearest-feature field, or 0 if a dimension is 0 or the product is too large.
uint64_t field_voxels(const blob::ModelRecord& m) {
  return bounded_volume(m.field_dims, kMaxFieldVoxelsPerModel);
}

// What the records share, and how far the records so far reach.
struct TableWalk {
  const uint32_t* grid;
  uint64_t grid_count;
  const uint16_t* field;
  uint64_t field_count;  // 0: the blob has no field
  uint32_t field_slots;
  uint64_t next_feature;
  uint64_t next_grid;
  uint64_t next_field;
};

// The model's field: absent with the blob's, else in range after the
// previous model's, every slot one of the model's features or empty.
bool field_of_model_ok(const blob::ModelRecord& m, TableWalk* w) {
  if (w->field_count == 0u)
    return m.field_dims[0] == 0u && m.field_dims[1] == 0u && m.field_dims[2] == 0u && m.field_base == 0u;
  const uint64_t voxels = field_voxels(m);
  if (voxels == 0u || m.field_base < w->next_field) return false;
  const uint64_t end = static_cast<uint64_t>(m.field_base) + voxels * w->field_slots;
  if (end > w->field_count) return false;
  for (uint64_t e = m.field_base; e < end; ++e) {
    if (w->field[e] != blob::kNoFieldFeature && w->field[e] >= m.feature_count) return false;
  }
  w->next_field = end;
  return true;
}

// One record; the walk advances past what it owns.
bool model_ok(const blob::ModelRecord& m, TableWalk* w) {
  if (!name_ok(m.name) || !geometry_ok(m) || m.vehicle_class >= kVehicleClassCount ||
      !model_group_allowed(m.vehicle_class, m.vehicle_group))
    return false;
  if (m.first_feature != w->next_feature || m.feature_count == 0u) return false;
  const uint64_t cells = grid_cells(m);
  if (cells == 0u || m.grid_offset_base < w->next_grid) return false;
  const uint64_t grid_end = static_cast<uint64_t>(m.grid_offset_base) + cells + 1u;
  if (grid_end > w->grid_count) return false;
  if (!grid_offsets_ok(w->grid + m.grid_offset_base, cells, m.feature_count)) return false;
  if (!field_of_model_ok(m, w)) return false;
  w->next_feature += m.feature_count;
  w->next_grid = grid_end;
  return true;
}

}  // namespace

Status check_models(const Sections& s) {
  const blob::Params& p = params_of(s);
  const blob::ModelRecord* models = section_as<blob::ModelRecord>(s, blob::kModels);
  TableWalk w{section_as<uint32_t>(s, blob::kGridOffsets),
              p.grid_offset_count,
              section_as<uint16_t>(s, blob::kNearestField),
              p.field_entry_count,
              p.field_slots,
              0u,
              0u,
              0u};
  for (uint32_t i = 0; i < p.model_count && i < kMaxModels; ++i) {
    if (!model_ok(models[i], &w)) return Status::kBlobBadModelTable;
  }
  return w.next_feature == p.feature_count ? Status::kOk : Status::kBlobBadModelTable;
}

}  // namespace blob_check
}  // namespace spinhash
