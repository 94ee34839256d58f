// Read-only view of a validated database blob. Database::open checks every
// offset, size, count, checksum and stored value before anything else reads
// the blob; afterwards the accessors trust it. No copies: the caller keeps
// the bytes alive (flash, mmap, static array) for as long as the view is used.
#pragma once
#include <cstddef>
#include <cstdint>

#include "spinhash/blob_format.hpp"
#include "spinhash/calibration.hpp"
#include "spinhash/config.hpp"
#include "spinhash/status.hpp"

namespace spinhash {

class Database {
 public:
  // bytes must be aligned to kBufferAlignment (mmap and alignas(64) arrays are).
  static Status open(const void* bytes, size_t size, Database* out) noexcept;

  bool is_open() const noexcept { return base_ != nullptr; }
  const blob::Header& header() const noexcept { return *header_; }
  const blob::Params& params() const noexcept { return *params_; }
  FeatureParams feature_params() const noexcept;  // the extraction settings of the blob

  uint32_t model_count() const noexcept { return params_->model_count; }
  uint32_t feature_count() const noexcept { return params_->feature_count; }
  uint32_t spin_dims() const noexcept { return params_->bins_alpha * params_->bins_beta; }
  const blob::ModelRecord& model(uint32_t i) const noexcept { return models_[i]; }

  const float* positions() const noexcept { return positions_; }  // 3 per feature
  const int16_t* normals() const noexcept { return normals_; }    // 3 per feature, * 1/32767
  const uint16_t* feature_models() const noexcept { return feature_models_; }
  const uint8_t* spin(uint32_t feature) const noexcept {
    return spins_ + static_cast<size_t>(feature) * spin_dims();
  }
  const uint32_t* grid_offsets() const noexcept { return grid_offsets_; }
  const blob::LshBit* lsh_bits(uint32_t table) const noexcept {
    return lsh_bits_ + static_cast<size_t>(table) * params_->lsh_bits;
  }
  const uint32_t* lsh_offsets(uint32_t table) const noexcept {
    return lsh_offsets_ + static_cast<size_t>(table) * (params_->lsh_buckets + 1u);
  }
  const uint32_t* lsh_entries() const noexcept { return lsh_entries_; }  // offsets index this
  bool has_nearest_field() const noexcept { return params_->field_entry_count > 0u; }
  const uint16_t* nearest_field() const noexcept { return nearest_field_; }  // blob_format.hpp
  // The thresholds of the answer levels' flags (calibration.hpp).
  const Calibration& calibration() const noexcept { return calibration_; }

  // Model index whose name equals `name`, or -1.
  int32_t find_model(const char* name) const noexcept;

 private:
  const uint8_t* base_ = nullptr;
  const blob::Header* header_ = nullptr;
  const blob::Params* params_ = nullptr;
  const blob::ModelRecord* models_ = nullptr;
  const float* positions_ = nullptr;
  const int16_t* normals_ = nullptr;
  const uint16_t* feature_models_ = nullptr;
  const uint8_t* spins_ = nullptr;
  const uint32_t* grid_offsets_ = nullptr;
  const blob::LshBit* lsh_bits_ = nullptr;
  const uint32_t* lsh_offsets_ = nullptr;
  const uint32_t* lsh_entries_ = nullptr;
  const uint16_t* nearest_field_ = nullptr;
  Calibration calibration_;
};

// CRC-32C (Castagnoli, reflected, init and xorout 0xFFFFFFFF), as in the blob.
uint32_t crc32c(const void* data, size_t size, uint32_t crc = 0) noexcept;
// FNV-1a 64-bit, used for the header's config fingerprint.
uint64_t fnv1a64(const void* data, size_t size) noexcept;
// Normal component <-> int16 storage (snorm16).
inline int16_t encode_normal_component(float v) {
  if (!(v == v)) return 0;  // NaN: the cast below would be undefined
  float c = v < -1.0f ? -1.0f : (v > 1.0f ? 1.0f : v);
  float s = c * 32767.0f;
  return static_cast<int16_t>(s >= 0.0f ? s + 0.5f : s - 0.5f);
}
inline float decode_normal_component(int16_t v) { return static_cast<float>(v) * (1.0f / 32767.0f); }

}  // namespace spinhash
