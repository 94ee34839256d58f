// Builds database content from model point clouds with the core's own feature
// code: features -> quantisation scale -> per-model grids -> LSH tables.
// Pure C++ (no Assimp/Embree), so the core tests can build blobs on a target.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "blob/blob_content.hpp"
#include "db/nearest_field.hpp"
#include "spinhash/config.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash {
namespace host {

struct ModelCloud {
  std::string name;         // <= kMaxModelNameBytes - 1 bytes
  std::vector<double> xyz;  // model frame, metres
  VehicleClass vehicle_class = VehicleClass::kUnclassified;
  // Its own group, only for a class in no group (model_group_allowed); kNone: the class's.
  VehicleGroup vehicle_group = VehicleGroup::kNone;
};

struct BuildOptions {
  FeatureParams features;             // spin_quant_scale is chosen from the data
  uint32_t lsh_tables = 8;            // L
  uint32_t lsh_bits = 24;             // K
  float quant_percentile = 0.999f;    // bin value mapped to 255
  float lsh_range_quantile = 0.999f;  // per-dimension range C_i of the LSH bits (eq. 2's d_c = sum C_i)
  float grid_cell = 0.6f;  // m, per-model feature grid (= the default Delta_max: 27 cells per lookup)
  FieldOptions field;  // nearest-feature field (field.cell = 0: none; a smaller blob, slower verification)
  uint32_t max_points_per_model = 1u << 21;
  uint32_t max_features_per_model = 1u << 14;
  uint64_t seed = 1;  // LSH bit sampling
};

struct BuildReport {
  uint32_t features = 0;
  std::vector<uint32_t> features_per_model;
  uint32_t max_bucket = 0;   // largest LSH bucket
  double mean_bucket = 0.0;  // mean non-empty bucket size
};

// Progress callback: (models done, models total).
using BuildProgress = void (*)(uint32_t done, uint32_t total, void* user);

bool build_database(const std::vector<ModelCloud>& models, const BuildOptions& opt, BlobContent* out,
                    BuildReport* report, std::string* error, BuildProgress progress = nullptr,
                    void* user = nullptr);

}  // namespace host
}  // namespace spinhash
