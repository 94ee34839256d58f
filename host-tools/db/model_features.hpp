// Features of one model cloud, unquantised, in the model frame.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "spinhash/config.hpp"

namespace spinhash {
namespace host {

struct ModelFeatures {
  std::vector<float> positions;  // 3 per feature
  std::vector<float> normals;    // 3 per feature
  std::vector<float> spins;      // dims per feature, sum 1
  uint32_t count = 0;
};

bool extract_model_features(const std::vector<double>& xyz, const FeatureParams& fp, uint32_t max_points,
                            uint32_t max_features, ModelFeatures* out, std::string* error);

}  // namespace host
}  // namespace spinhash
