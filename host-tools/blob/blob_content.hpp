// Everything a blob holds, as plain host vectors in native byte order.
#pragma once
#include <cstdint>
#include <vector>

#include "blob/calibration_content.hpp"
#include "spinhash/blob_format.hpp"

namespace spinhash {
namespace host {

struct BlobContent {
  blob::Params params{};                  // counts must match the vectors below
  std::vector<blob::ModelRecord> models;  // model_count
  std::vector<float> positions;           // 3 * feature_count
  std::vector<int16_t> normals;           // 3 * feature_count, encode_normal_component
  std::vector<uint16_t> feature_models;   // feature_count
  std::vector<uint8_t> spins;             // bins_alpha * bins_beta * feature_count
  std::vector<uint32_t> grid_offsets;     // grid_offset_count
  std::vector<blob::LshBit> lsh_bits;     // lsh_tables * lsh_bits
  std::vector<uint32_t> lsh_offsets;      // lsh_tables * (lsh_buckets + 1)
  std::vector<uint32_t> lsh_entries;      // lsh_tables * feature_count
  std::vector<uint16_t> nearest_field;    // field_entry_count
  CalibrationContent calibration = priors_calibration();
};

}  // namespace host
}  // namespace spinhash
