#include "db/tiny_blob.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "db/nearest_field.hpp"
#include "spinhash/database.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash {
namespace host {
namespace {

constexpr uint32_t kBins = 4;  // 4 x 4 spin images
constexpr uint32_t kTables = 3;
constexpr uint32_t kBitsPerKey = 6;
constexpr uint32_t kBuckets = 16;
constexpr float kGridCell = 0.5f;
constexpr uint32_t kMaxSpinValue = 60;  // sum-normalised spins quantised at 1000 stay small
constexpr uint32_t kMaxNormalDraws = 64;
constexpr float kFieldCell = 0.25f;  // two field voxels per grid cell
constexpr uint32_t kFieldSlots = 2;

// splitmix64: the same sequence everywhere, unlike <random> distributions.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t next() { return blob::mix64(state_ += 0x9E3779B97F4A7C15ull); }
  float unit() { return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f); }  // [0, 1)
  uint32_t below(uint32_t n) { return static_cast<uint32_t>(next() % n); }

 private:
  uint64_t state_;
};

blob::Params tiny_params(uint32_t models, uint32_t features) {
  blob::Params p{};
  p.model_count = models;
  p.feature_count = features;
  p.bins_alpha = kBins;
  p.bins_beta = kBins;
  p.lsh_tables = kTables;
  p.lsh_bits = kBitsPerKey;
  p.lsh_buckets = kBuckets;
  p.cloud_voxel = 0.08f;
  p.normal_radius = 0.3f;
  p.basis_spacing = 0.25f;
  p.support_radius = 1.0f;
  p.support_angle_deg = 60.0f;
  p.spin_quant_scale = 1000.0f;
  p.grid_cell = kGridCell;
  p.field_slots = kFieldSlots;
  p.field_cell = kFieldCell;
  p.field_reach = kGridCell;
  return p;
}

void add_unit_normal(Rng& rng, std::vector<int16_t>* normals) {
  float v[3] = {0.0f, 0.0f, 1.0f};
  for (uint32_t draw = 0; draw < kMaxNormalDraws; ++draw) {
    const float c[3] = {rng.unit() * 2.0f - 1.0f, rng.unit() * 2.0f - 1.0f, rng.unit() * 2.0f - 1.0f};
    const float len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (len > 0.1f && len <= 1.0f) {
      for (int k = 0; k < 3; ++k) v[k] = c[k] / len;
      break;
    }
  }
  for (float c : v) normals->push_back(encode_normal_component(c));
}

uint32_t cell_of(const float* p, const blob::ModelRecord& m) {
  uint32_t idx[3];
  for (int k = 0; k < 3; ++k) {
    const float f = std::floor((p[k] - m.grid_origin[k]) / kGridCell);
    idx[k] = f <= 0.0f ? 0u : std::min(static_cast<uint32_t>(f), m.grid_dims[k] - 1u);
  }
  return idx[0] + m.grid_dims[0] * (idx[1] + m.grid_dims[1] * idx[2]);
}

// The model's nearest-feature field from its features as appended.
void add_field(BlobContent* c, blob::ModelRecord* m) {
  FieldOptions opt;
  opt.cell = c->params.field_cell;
  opt.reach = c->params.field_reach;
  opt.slots = c->params.field_slots;
  append_nearest_field(opt, m, c);  // a few features in a small box: always fits
}

// Features of model i: random points in its grid box, sorted by cell, plus the
// grid's CSR offsets.
void add_model(uint32_t i, uint32_t count, Rng& rng, BlobContent* c) {
  blob::ModelRecord m{};
  std::snprintf(m.name, sizeof(m.name), "tiny_%u", i);
  m.vehicle_class = static_cast<uint8_t>(1u + i % (kVehicleClassCount - 1u));  // every class but unclassified
  m.first_feature = static_cast<uint32_t>(c->feature_models.size());
  m.feature_count = count;
  m.grid_dims[0] = 1u + i % 3u;
  m.grid_dims[1] = 1u + i % 2u;
  m.grid_dims[2] = 1u;
  m.grid_offset_base = static_cast<uint32_t>(c->grid_offsets.size());
  std::vector<float> pts(3u * count);
  for (uint32_t f = 0; f < count; ++f) {
    for (uint32_t k = 0; k < 3u; ++k) pts[3u * f + k] = rng.unit() * kGridCell * m.grid_dims[k];
  }
  std::vector<uint32_t> cell(count), order(count);
  for (uint32_t f = 0; f < count; ++f) cell[f] = cell_of(&pts[3u * f], m);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return cell[a] < cell[b]; });
  const uint32_t cells = m.grid_dims[0] * m.grid_dims[1] * m.grid_dims[2];
  std::vector<uint32_t> offsets(cells + 1u, 0u);
  for (int k = 0; k < 3; ++k) {
    m.bbox_min[k] = pts.empty() ? 0.0f : pts[k];
    m.bbox_max[k] = m.bbox_min[k];
  }
  for (uint32_t f : order) {
    ++offsets[cell[f] + 1u];
    for (uint32_t k = 0; k < 3u; ++k) {
      const float v = pts[3u * f + k];
      c->positions.push_back(v);
      m.bbox_min[k] = std::min(m.bbox_min[k], v);
      m.bbox_max[k] = std::max(m.bbox_max[k], v);
    }
    add_unit_normal(rng, &c->normals);
    c->feature_models.push_back(static_cast<uint16_t>(i));
    for (uint32_t d = 0; d < kBins * kBins; ++d)
      c->spins.push_back(static_cast<uint8_t>(rng.below(kMaxSpinValue + 1u)));
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  c->grid_offsets.insert(c->grid_offsets.end(), offsets.begin(), offsets.end());
  add_field(c, &m);
  c->models.push_back(m);
}

uint64_t key_of(const uint8_t* spin, const blob::LshBit* bits) {
  uint64_t key = 0;
  for (uint32_t k = 0; k < kBitsPerKey; ++k) {
    if (spin[bits[k].dim] > bits[k].threshold) key |= uint64_t{1} << k;
  }
  return key;
}

// Bits with thresholds inside each dimension's range, and CSR buckets per table.
void add_lsh(Rng& rng, BlobContent* c) {
  const uint32_t n = c->params.feature_count;
  const uint32_t dims = kBins * kBins;
  float dc = 0.0f;
  for (uint32_t d = 0; d < dims; ++d) {
    uint8_t lo = 255, hi = 0;
    for (uint32_t f = 0; f < n; ++f) {
      lo = std::min(lo, c->spins[f * dims + d]);
      hi = std::max(hi, c->spins[f * dims + d]);
    }
    dc += static_cast<float>(hi - lo);
  }
  c->params.lsh_dc = dc;
  for (uint32_t j = 0; j < kTables * kBitsPerKey; ++j) {
    c->lsh_bits.push_back(
        {static_cast<uint16_t>(rng.below(dims)), static_cast<uint16_t>(rng.below(kMaxSpinValue))});
  }
  for (uint32_t t = 0; t < kTables; ++t) {
    std::vector<uint32_t> bucket(n);
    std::vector<uint32_t> offsets(kBuckets + 1u, 0u);
    for (uint32_t f = 0; f < n; ++f) {
      bucket[f] = blob::bucket_of(key_of(&c->spins[f * dims], &c->lsh_bits[t * kBitsPerKey]), t, kBuckets);
      ++offsets[bucket[f] + 1u];
    }
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    std::vector<uint32_t> entries(n), fill(offsets.begin(), offsets.end() - 1);
    for (uint32_t f = 0; f < n; ++f) entries[fill[bucket[f]]++] = f;
    c->lsh_offsets.insert(c->lsh_offsets.end(), offsets.begin(), offsets.end());
    c->lsh_entries.insert(c->lsh_entries.end(), entries.begin(), entries.end());
  }
}

}  // namespace

BlobContent make_tiny_blob_content(uint32_t models, uint32_t features_per_model, uint64_t seed) {
  BlobContent c;
  c.params = tiny_params(models, models * features_per_model);
  Rng rng(seed);
  for (uint32_t i = 0; i < models; ++i) add_model(i, features_per_model, rng, &c);
  c.params.grid_offset_count = static_cast<uint32_t>(c.grid_offsets.size());
  c.params.field_entry_count = static_cast<uint32_t>(c.nearest_field.size());
  add_lsh(rng, &c);
  return c;
}

}  // namespace host
}  // namespace spinhash
