#include "db/nearest_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "db/model_grid.hpp"
#include "spinhash/blob_format.hpp"
#include "spinhash/limits.hpp"
#include "util/angles.hpp"

namespace spinhash {
namespace host {
namespace {

constexpr float kHalfDiagonal = 0.8660254f;  // sqrt(3) / 2: a voxel's half-diagonal per unit edge
constexpr float kNormalScale = 1.0f / 32767.0f;

struct Candidate {
  float dist2;
  uint16_t feature;
  bool operator<(const Candidate& o) const {
    return dist2 < o.dist2 || (dist2 == o.dist2 && feature < o.feature);
  }
};

float normal_dot(const int16_t* a, const int16_t* b) {
  return (static_cast<float>(a[0]) * static_cast<float>(b[0]) +
          static_cast<float>(a[1]) * static_cast<float>(b[1]) +
          static_cast<float>(a[2]) * static_cast<float>(b[2])) *
         (kNormalScale * kNormalScale);
}

// Features within radius of centre, from the 27 helper cells around it (cells of edge >= radius).
void gather(const float* positions, const ModelGrid& helper, float helper_cell, const float centre[3],
            float radius2, std::vector<Candidate>* out) {
  out->clear();
  int32_t c[3];
  for (int a = 0; a < 3; ++a)
    c[a] = static_cast<int32_t>(std::floor((centre[a] - helper.origin[a]) / helper_cell));
  for (int32_t k = c[2] - 1; k <= c[2] + 1; ++k)
    for (int32_t j = c[1] - 1; j <= c[1] + 1; ++j)
      for (int32_t i = c[0] - 1; i <= c[0] + 1; ++i) {
        if (i < 0 || j < 0 || k < 0 || i >= static_cast<int32_t>(helper.dims[0]) ||
            j >= static_cast<int32_t>(helper.dims[1]) || k >= static_cast<int32_t>(helper.dims[2]))
          continue;
        const uint32_t cell =
            static_cast<uint32_t>(i) +
            helper.dims[0] * (static_cast<uint32_t>(j) + helper.dims[1] * static_cast<uint32_t>(k));
        for (uint32_t o = helper.offsets[cell]; o < helper.offsets[cell + 1u]; ++o) {
          const uint32_t f = helper.order[o];
          const float* p = positions + 3u * f;
          const float dx = p[0] - centre[0], dy = p[1] - centre[1], dz = p[2] - centre[2];
          const float d2 = dx * dx + dy * dy + dz * dz;
          if (d2 <= radius2) out->push_back({d2, static_cast<uint16_t>(f)});
        }
      }
  std::sort(out->begin(), out->end());
}

// Slots in two passes over the candidates, nearest first: one per face (a
// normal more than the split angle from every chosen one), so an edge or a
// corner keeps a feature of each face; then the nearest of the rest, so a
// flat patch keeps the few features around the centre.
void choose_slots(const std::vector<Candidate>& near, const int16_t* normals, uint32_t slots, float cos_split,
                  uint16_t* out) {
  uint32_t used = 0;
  auto chosen = [&](uint16_t f) { return std::find(out, out + used, f) != out + used; };
  for (const Candidate& c : near) {
    if (used == slots) break;
    bool new_face = true;
    for (uint32_t s = 0; s < used && new_face; ++s)
      new_face = normal_dot(normals + 3u * c.feature, normals + 3u * out[s]) < cos_split;
    if (new_face) out[used++] = c.feature;
  }
  for (const Candidate& c : near) {
    if (used == slots) break;
    if (!chosen(c.feature)) out[used++] = c.feature;
  }
  for (; used < slots; ++used) out[used] = blob::kNoFieldFeature;
}

}  // namespace

bool append_nearest_field(const FieldOptions& opt, blob::ModelRecord* record, BlobContent* content) {
  if (!(opt.cell > 0.0f) || opt.slots == 0u) return true;  // no field asked for
  const uint32_t count = record->feature_count;
  if (count >= blob::kNoFieldFeature || opt.slots > kMaxFieldSlots || !(opt.reach >= 0.0f)) return false;
  uint32_t dims[3];
  uint64_t voxels = 1;
  float origin[3];
  for (int a = 0; a < 3; ++a) {
    origin[a] = record->grid_origin[a] - opt.reach;
    dims[a] = static_cast<uint32_t>(std::ceil((record->bbox_max[a] - origin[a] + opt.reach) / opt.cell));
    dims[a] = std::max(dims[a], 1u);
    voxels *= dims[a];
  }
  if (voxels > kMaxFieldVoxelsPerModel) return false;
  const size_t base = content->nearest_field.size(), entries = static_cast<size_t>(voxels) * opt.slots;
  if (entries > UINT32_MAX - base) return false;
  const float* positions = content->positions.data() + 3u * record->first_feature;
  const int16_t* normals = content->normals.data() + 3u * record->first_feature;
  const float radius = opt.reach + kHalfDiagonal * opt.cell;
  const ModelGrid helper =
      build_model_grid(std::vector<float>(positions, positions + 3u * count), count, radius);
  const float cos_split = static_cast<float>(std::cos(static_cast<double>(opt.split_deg) * kDegToRad));
  content->nearest_field.resize(base + entries);
  std::vector<Candidate> near;
  size_t at = base;
  for (uint32_t k = 0; k < dims[2]; ++k)
    for (uint32_t j = 0; j < dims[1]; ++j)
      for (uint32_t i = 0; i < dims[0]; ++i, at += opt.slots) {
        const float centre[3] = {origin[0] + (static_cast<float>(i) + 0.5f) * opt.cell,
                                 origin[1] + (static_cast<float>(j) + 0.5f) * opt.cell,
                                 origin[2] + (static_cast<float>(k) + 0.5f) * opt.cell};
        gather(positions, helper, radius, centre, radius * radius, &near);
        choose_slots(near, normals, opt.slots, cos_split, &content->nearest_field[at]);
      }
  record->field_base = static_cast<uint32_t>(base);
  for (int a = 0; a < 3; ++a) record->field_dims[a] = dims[a];
  return true;
}

}  // namespace host
}  // namespace spinhash
