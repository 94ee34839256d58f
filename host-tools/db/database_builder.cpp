#include "db/database_builder.hpp"

#include <algorithm>
#include <cstring>

#include "db/lsh_tables.hpp"
#include "db/model_features.hpp"
#include "db/model_grid.hpp"
#include "spinhash/database.hpp"
#include "spinhash/internal/spin_quantize.hpp"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace host {
namespace {

constexpr uint32_t kMinFeaturesPerModel = 2;  // a doublet needs two

// Bin value at `percentile` of all non-zero bins, mapped to 255 by the scale.
float choose_quant_scale(const std::vector<ModelFeatures>& feats, float percentile) {
  std::vector<float> values;
  for (const ModelFeatures& m : feats)
    for (float v : m.spins)
      if (v > 0.0f) values.push_back(v);
  if (values.empty()) return 255.0f;
  size_t k =
      std::min(values.size() - 1u, static_cast<size_t>(percentile * static_cast<float>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return 255.0f / values[k];
}

blob::ModelRecord make_record(const ModelCloud& model, uint32_t first, uint32_t count, const ModelGrid& g,
                              uint32_t grid_base, const ModelFeatures& mf) {
  blob::ModelRecord r;
  std::memset(&r, 0, sizeof r);
  std::memcpy(r.name, model.name.data(), model.name.size());
  r.vehicle_class = static_cast<uint8_t>(model.vehicle_class);
  r.vehicle_group = static_cast<uint8_t>(model.vehicle_group);
  r.first_feature = first;
  r.feature_count = count;
  r.grid_offset_base = grid_base;
  for (int a = 0; a < 3; ++a) {
    r.grid_dims[a] = g.dims[a];
    r.grid_origin[a] = g.origin[a];
    r.bbox_min[a] = 1e30f;
    r.bbox_max[a] = -1e30f;
  }
  for (uint32_t i = 0; i < mf.count; ++i)
    for (int a = 0; a < 3; ++a) {
      r.bbox_min[a] = std::min(r.bbox_min[a], mf.positions[3u * i + a]);
      r.bbox_max[a] = std::max(r.bbox_max[a], mf.positions[3u * i + a]);
    }
  return r;
}

// Appends one model's features in grid order, quantised, to the content.
void append_model(BlobContent* c, uint16_t model, const ModelFeatures& mf, const ModelGrid& g, float scale,
                  uint32_t dims) {
  std::vector<uint8_t> q(dims);
  for (uint32_t i : g.order) {
    for (int a = 0; a < 3; ++a) {
      c->positions.push_back(mf.positions[3u * i + a]);
      c->normals.push_back(encode_normal_component(mf.normals[3u * i + a]));
    }
    c->feature_models.push_back(model);
    quantize_spin(mf.spins.data() + static_cast<size_t>(i) * dims, dims, scale, q.data());
    c->spins.insert(c->spins.end(), q.begin(), q.end());
  }
  c->grid_offsets.insert(c->grid_offsets.end(), g.offsets.begin(), g.offsets.end());
}

void fill_params(const BuildOptions& opt, const BlobContent& c, float scale, const LshTables& lsh,
                 blob::Params* p) {
  std::memset(p, 0, sizeof *p);
  p->model_count = static_cast<uint32_t>(c.models.size());
  p->feature_count = static_cast<uint32_t>(c.feature_models.size());
  p->bins_alpha = opt.features.bins_alpha;
  p->bins_beta = opt.features.bins_beta;
  p->lsh_tables = opt.lsh_tables;
  p->lsh_bits = opt.lsh_bits;
  p->lsh_buckets = lsh.buckets;
  p->grid_offset_count = static_cast<uint32_t>(c.grid_offsets.size());
  p->cloud_voxel = opt.features.cloud_voxel;
  p->normal_radius = opt.features.normal_radius;
  p->basis_spacing = opt.features.basis_spacing;
  p->support_radius = opt.features.support_radius;
  p->support_angle_deg = opt.features.support_angle_deg;
  p->spin_quant_scale = scale;
  p->lsh_dc = lsh.d_c;
  p->grid_cell = opt.grid_cell;
  const bool field = !c.nearest_field.empty();
  p->field_entry_count = static_cast<uint32_t>(c.nearest_field.size());
  p->field_slots = field ? opt.field.slots : 0u;
  p->field_cell = field ? opt.field.cell : 0.0f;
  p->field_reach = field ? opt.field.reach : 0.0f;
}

// The model's field, from its features as appended, into its record and the content.
bool append_field(BlobContent* c, const BuildOptions& opt, std::string* error) {
  if (append_nearest_field(opt.field, &c->models.back(), c)) return true;
  *error = std::string("model '") + c->models.back().name +
           "': too many features or voxels for the nearest-feature field, or a field past 32-bit offsets";
  return false;
}

bool check_inputs(const std::vector<ModelCloud>& models, const BuildOptions& opt, std::string* error) {
  if (models.empty() || models.size() > kMaxModels) {
    *error = "need between 1 and " + std::to_string(kMaxModels) + " models";
    return false;
  }
  for (const ModelCloud& m : models) {
    if (m.name.empty() || m.name.size() >= kMaxModelNameBytes) {
      *error =
          "model name '" + m.name + "' must be 1 to " + std::to_string(kMaxModelNameBytes - 1) + " bytes";
      return false;
    }
    if (static_cast<uint32_t>(m.vehicle_class) >= kVehicleClassCount) {
      *error = "model '" + m.name + "': no such vehicle class";
      return false;
    }
    if (!model_group_allowed(static_cast<uint32_t>(m.vehicle_class),
                             static_cast<uint32_t>(m.vehicle_group))) {
      *error = "model '" + m.name + "': group '" + vehicle_group_name(m.vehicle_group) + "', but class '" +
               vehicle_class_name(static_cast<uint32_t>(m.vehicle_class)) +
               "' has its own group: only a model of a class in no group takes a group of its own";
      return false;
    }
  }
  if (opt.lsh_tables < 1 || opt.lsh_tables > kMaxLshTables || opt.lsh_bits < 1 ||
      opt.lsh_bits > kMaxLshBits) {
    *error = "LSH tables must be 1.." + std::to_string(kMaxLshTables) + " and bits 1.." +
             std::to_string(kMaxLshBits);
    return false;
  }
  if (!(opt.grid_cell > 0.0f)) {
    *error = "grid cell must be positive";
    return false;
  }
  if (!(opt.field.cell >= 0.0f) || !(opt.field.reach >= 0.0f) || opt.field.slots > kMaxFieldSlots) {
    *error = "field cell and reach must be >= 0 and slots 0.." + std::to_string(kMaxFieldSlots);
    return false;
  }
  return true;
}

}  // namespace

bool build_database(const std::vector<ModelCloud>& models, const BuildOptions& opt, BlobContent* out,
                    BuildReport* report, std::string* error, BuildProgress progress, void* user) {
  if (!check_inputs(models, opt, error)) return false;
  const uint32_t dims = spin_dims(opt.features);
  std::vector<ModelFeatures> feats(models.size());
  for (size_t i = 0; i < models.size(); ++i) {
    std::string why;
    if (!extract_model_features(models[i].xyz, opt.features, opt.max_points_per_model,
                                opt.max_features_per_model, &feats[i], &why)) {
      *error = "model '" + models[i].name + "': " + why;
      return false;
    }
    if (feats[i].count < kMinFeaturesPerModel) {
      *error = "model '" + models[i].name + "' gives only " + std::to_string(feats[i].count) + " features";
      return false;
    }
    if (progress != nullptr)
      progress(static_cast<uint32_t>(i + 1), static_cast<uint32_t>(models.size()), user);
  }
  const float scale = choose_quant_scale(feats, opt.quant_percentile);
  BlobContent c;
  report->features_per_model.clear();
  for (size_t i = 0; i < models.size(); ++i) {
    ModelGrid g = build_model_grid(feats[i].positions, feats[i].count, opt.grid_cell);
    c.models.push_back(make_record(models[i], static_cast<uint32_t>(c.feature_models.size()), feats[i].count,
                                   g, static_cast<uint32_t>(c.grid_offsets.size()), feats[i]));
    append_model(&c, static_cast<uint16_t>(i), feats[i], g, scale, dims);
    if (!append_field(&c, opt, error)) return false;
    report->features_per_model.push_back(feats[i].count);
  }
  const uint32_t total = static_cast<uint32_t>(c.feature_models.size());
  LshTables lsh =
      build_lsh_tables(c.spins, dims, total, opt.lsh_tables, opt.lsh_bits, opt.lsh_range_quantile, opt.seed);
  c.lsh_bits = std::move(lsh.bits);
  c.lsh_offsets = std::move(lsh.offsets);
  c.lsh_entries = std::move(lsh.entries);
  fill_params(opt, c, scale, lsh, &c.params);
  report->features = total;
  report->max_bucket = lsh.max_bucket;
  report->mean_bucket = lsh.mean_bucket;
  *out = std::move(c);
  return true;
}

}  // namespace host
}  // namespace spinhash
