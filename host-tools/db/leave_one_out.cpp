#include "db/leave_one_out.hpp"

#include <algorithm>

namespace spinhash {
namespace host {
namespace {

uint64_t cells_of(const blob::ModelRecord& r) {
  return static_cast<uint64_t>(r.grid_dims[0]) * r.grid_dims[1] * r.grid_dims[2];
}

uint64_t field_entries_of(const blob::ModelRecord& r, uint32_t slots) {
  return static_cast<uint64_t>(r.field_dims[0]) * r.field_dims[1] * r.field_dims[2] * slots;
}

template <typename T>
void erase_range(std::vector<T>* v, uint64_t begin, uint64_t count) {
  v->erase(v->begin() + static_cast<std::ptrdiff_t>(begin),
           v->begin() + static_cast<std::ptrdiff_t>(begin + count));
}

// Every table's buckets without the features [first, first + count), the
// later ones renumbered; the buckets keep their order.
void drop_from_lsh(const BlobContent& full, uint32_t first, uint32_t count, BlobContent* out) {
  const blob::Params& p = full.params;
  const uint32_t n = p.feature_count, buckets = p.lsh_buckets;
  out->lsh_offsets.assign(static_cast<size_t>(p.lsh_tables) * (buckets + 1u), 0u);
  out->lsh_entries.clear();
  out->lsh_entries.reserve(static_cast<size_t>(p.lsh_tables) * (n - count));
  for (uint32_t t = 0; t < p.lsh_tables; ++t) {
    const uint32_t* off = full.lsh_offsets.data() + static_cast<size_t>(t) * (buckets + 1u);
    const uint32_t* entries = full.lsh_entries.data() + static_cast<size_t>(t) * n;
    uint32_t* new_off = out->lsh_offsets.data() + static_cast<size_t>(t) * (buckets + 1u);
    uint32_t kept = 0;
    for (uint32_t b = 0; b < buckets; ++b) {
      new_off[b] = kept;
      for (uint32_t k = off[b]; k < off[b + 1u]; ++k) {
        const uint32_t f = entries[k];
        if (f >= first && f < first + count) continue;
        out->lsh_entries.push_back(f < first ? f : f - count);
        ++kept;
      }
    }
    new_off[buckets] = kept;
  }
}

}  // namespace

bool without_model(const BlobContent& full, uint32_t model, BlobContent* out) {
  const blob::Params& p = full.params;
  if (p.model_count < 2u || model >= p.model_count || full.models.size() != p.model_count) return false;
  const blob::ModelRecord& gone = full.models[model];
  const uint32_t first = gone.first_feature, count = gone.feature_count;
  const uint64_t cells = cells_of(gone) + 1u;
  const uint64_t field = field_entries_of(gone, p.field_slots);
  const uint32_t dims = p.bins_alpha * p.bins_beta;
  BlobContent c;
  c.params = p;
  for (uint32_t m = 0; m < p.model_count; ++m) {
    if (m == model) continue;
    blob::ModelRecord r = full.models[m];
    if (m > model) {
      r.first_feature -= count;
      r.grid_offset_base -= static_cast<uint32_t>(cells);
      if (p.field_entry_count > 0u) r.field_base -= static_cast<uint32_t>(field);
    }
    c.models.push_back(r);
  }
  c.positions = full.positions;
  erase_range(&c.positions, 3u * static_cast<uint64_t>(first), 3u * static_cast<uint64_t>(count));
  c.normals = full.normals;
  erase_range(&c.normals, 3u * static_cast<uint64_t>(first), 3u * static_cast<uint64_t>(count));
  c.spins = full.spins;
  erase_range(&c.spins, static_cast<uint64_t>(dims) * first, static_cast<uint64_t>(dims) * count);
  c.feature_models = full.feature_models;
  erase_range(&c.feature_models, first, count);
  for (uint16_t& m : c.feature_models)
    if (m > model) --m;
  c.grid_offsets = full.grid_offsets;
  erase_range(&c.grid_offsets, gone.grid_offset_base, cells);
  c.nearest_field = full.nearest_field;
  if (p.field_entry_count > 0u) erase_range(&c.nearest_field, gone.field_base, field);
  c.lsh_bits = full.lsh_bits;
  drop_from_lsh(full, first, count, &c);
  c.params.model_count = p.model_count - 1u;
  c.params.feature_count = p.feature_count - count;
  c.params.grid_offset_count = static_cast<uint32_t>(c.grid_offsets.size());
  c.params.field_entry_count = static_cast<uint32_t>(c.nearest_field.size());
  *out = std::move(c);
  return true;
}

}  // namespace host
}  // namespace spinhash
