#include "db/model_features.hpp"

#include "blob/aligned_bytes.hpp"
#include "spinhash/features.hpp"

namespace spinhash {
namespace host {

bool extract_model_features(const std::vector<double>& xyz, const FeatureParams& fp, uint32_t max_points,
                            uint32_t max_features, ModelFeatures* out, std::string* error) {
  const uint32_t n = static_cast<uint32_t>(xyz.size() / 3u);
  ExtractorCapacity cap;
  cap.max_points = n > 0 ? (n < max_points ? n : max_points) : 1u;
  cap.max_features = max_features;
  cap.max_spin_dims = spin_dims(fp);
  Arena counter;
  FeatureExtractor sizing;
  sizing.init(fp, cap, counter);
  AlignedBytes workspace(counter.used());
  Arena arena(workspace.data(), workspace.size());
  FeatureExtractor extractor;
  if (extractor.init(fp, cap, arena) != Status::kOk) {
    *error = "invalid feature parameters";
    return false;
  }
  CloudView cloud;
  cloud.xyz_d = xyz.data();
  cloud.count = n;
  FeatureSet fs;
  ExtractStats stats;
  Status s = extractor.extract(cloud, OrientationHint{}, &fs, &stats);
  if (s != Status::kOk) {
    *error = status_name(s);
    return false;
  }
  out->count = fs.count;
  out->positions.resize(3u * fs.count);
  out->normals.resize(3u * fs.count);
  out->spins.assign(fs.spins, fs.spins + static_cast<size_t>(fs.count) * fs.dims);
  for (uint32_t i = 0; i < 3u * fs.count; ++i) {  // back to the model frame
    out->positions[i] = static_cast<float>(static_cast<double>(fs.positions[i]) + fs.origin[i % 3u]);
    out->normals[i] = fs.normals[i];
  }
  return true;
}

}  // namespace host
}  // namespace spinhash
