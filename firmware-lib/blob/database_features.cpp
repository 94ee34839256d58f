// Stages 5 and 6 of Database::open: per-feature values and the LSH index.
// Runs after the model table, so model ranges are known to tile the features.
#include <cmath>

#include "blob/database_checks.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace blob_check {
namespace {

// Decoded normals must be unit length up to quantisation and a little slack.
constexpr float kMinNormalLengthSq = 0.9f * 0.9f;
constexpr float kMaxNormalLengthSq = 1.1f * 1.1f;
constexpr uint32_t kMaxSpinValue = 255;  // spins are uint8: larger thresholds never fire

bool feature_ok(const float* pos, const int16_t* nrm, uint16_t model_id, uint32_t model) {
  if (model_id != model) return false;
  if (!std::isfinite(pos[0]) || !std::isfinite(pos[1]) || !std::isfinite(pos[2])) return false;
  const float x = decode_normal_component(nrm[0]);
  const float y = decode_normal_component(nrm[1]);
  const float z = decode_normal_component(nrm[2]);
  const float len_sq = x * x + y * y + z * z;
  return len_sq >= kMinNormalLengthSq && len_sq <= kMaxNormalLengthSq;
}

bool table_offsets_ok(const uint32_t* off, uint32_t buckets, uint32_t feature_count) {
  if (off[0] != 0u || off[buckets] != feature_count) return false;
  for (uint32_t b = 0; b < buckets; ++b) {
    if (off[b + 1u] < off[b]) return false;
  }
  return true;
}

}  // namespace

Status check_features(const Sections& s) {
  const blob::Params& p = params_of(s);
  const blob::ModelRecord* models = section_as<blob::ModelRecord>(s, blob::kModels);
  const float* pos = section_as<float>(s, blob::kFeatPositions);
  const int16_t* nrm = section_as<int16_t>(s, blob::kFeatNormals);
  const uint16_t* ids = section_as<uint16_t>(s, blob::kFeatModels);
  for (uint32_t m = 0; m < p.model_count && m < kMaxModels; ++m) {
    const uint32_t end = models[m].first_feature + models[m].feature_count;  // <= feature_count
    for (uint32_t f = models[m].first_feature; f < end && f < kMaxFeatures; ++f) {
      const size_t k = static_cast<size_t>(f) * 3u;
      if (!feature_ok(pos + k, nrm + k, ids[f], m)) return Status::kBlobBadFeature;
    }
  }
  return Status::kOk;
}

Status check_lsh(const Sections& s) {
  const blob::Params& p = params_of(s);
  const blob::LshBit* bits = section_as<blob::LshBit>(s, blob::kLshBits);
  const uint32_t* offsets = section_as<uint32_t>(s, blob::kLshOffsets);
  const uint32_t* entries = section_as<uint32_t>(s, blob::kLshEntries);
  const uint32_t dims = p.bins_alpha * p.bins_beta;      // <= kMaxSpinDims
  const uint32_t bit_count = p.lsh_tables * p.lsh_bits;  // <= kMaxLshTables * kMaxLshBits
  for (uint32_t j = 0; j < bit_count; ++j) {
    if (bits[j].dim >= dims || bits[j].threshold > kMaxSpinValue) return Status::kBlobBadIndex;
  }
  const size_t stride = static_cast<size_t>(p.lsh_buckets) + 1u;
  for (uint32_t t = 0; t < p.lsh_tables && t < kMaxLshTables; ++t) {
    if (!table_offsets_ok(offsets + t * stride, p.lsh_buckets, p.feature_count)) {
      return Status::kBlobBadIndex;
    }
  }
  const uint64_t entry_count = static_cast<uint64_t>(p.lsh_tables) * p.feature_count;
  for (uint64_t j = 0; j < entry_count; ++j) {
    if (entries[j] >= p.feature_count) return Status::kBlobBadIndex;
  }
  return Status::kOk;
}

}  // namespace blob_check
}  // namespace spinhash
