// Database::open runs every validation stage (database_checks.hpp) before it
// touches `out`; the accessors then trust the blob without further checks.
#include "spinhash/database.hpp"

#include <cstdint>

#include "blob/database_checks.hpp"

namespace spinhash {
namespace {

Status validate(const uint8_t* base, size_t size, blob_check::Sections* sections) {
  Status s = blob_check::check_header(base, size);
  if (s != Status::kOk) return s;
  s = blob_check::check_sections(base, sections);
  if (s != Status::kOk) return s;
  s = blob_check::check_params(*reinterpret_cast<const blob::Header*>(base), *sections);
  if (s != Status::kOk) return s;
  s = blob_check::check_zero_fill(base, *sections);
  if (s != Status::kOk) return s;
  s = blob_check::check_models(*sections);
  if (s != Status::kOk) return s;
  s = blob_check::check_features(*sections);
  if (s != Status::kOk) return s;
  s = blob_check::check_lsh(*sections);
  if (s != Status::kOk) return s;
  return blob_check::check_calibration(*sections);
}

// Bounded strcmp: stored names are NUL-terminated within kMaxModelNameBytes.
bool name_equals(const char* stored, const char* name) {
  for (uint32_t k = 0; k < kMaxModelNameBytes; ++k) {
    if (stored[k] != name[k]) return false;
    if (stored[k] == '\0') return true;
  }
  return false;
}

}  // namespace

Status Database::open(const void* bytes, size_t size, Database* out) noexcept {
  if (bytes == nullptr || size == 0u || out == nullptr) return Status::kInvalidArgument;
  if (reinterpret_cast<uintptr_t>(bytes) % kBufferAlignment != 0u) {
    return Status::kMisalignedBuffer;
  }
  const uint8_t* base = static_cast<const uint8_t*>(bytes);
  blob_check::Sections sec{};
  const Status s = validate(base, size, &sec);
  if (s != Status::kOk) return s;

  using blob_check::section_as;
  Database db;
  db.base_ = base;
  db.header_ = reinterpret_cast<const blob::Header*>(base);
  db.params_ = section_as<blob::Params>(sec, blob::kParams);
  db.models_ = section_as<blob::ModelRecord>(sec, blob::kModels);
  db.positions_ = section_as<float>(sec, blob::kFeatPositions);
  db.normals_ = section_as<int16_t>(sec, blob::kFeatNormals);
  db.feature_models_ = section_as<uint16_t>(sec, blob::kFeatModels);
  db.spins_ = section_as<uint8_t>(sec, blob::kFeatSpins);
  db.grid_offsets_ = section_as<uint32_t>(sec, blob::kGridOffsets);
  db.lsh_bits_ = section_as<blob::LshBit>(sec, blob::kLshBits);
  db.lsh_offsets_ = section_as<uint32_t>(sec, blob::kLshOffsets);
  db.lsh_entries_ = section_as<uint32_t>(sec, blob::kLshEntries);
  db.nearest_field_ = section_as<uint16_t>(sec, blob::kNearestField);
  db.calibration_ = Calibration(sec.data[blob::kCalibration]);
  *out = db;
  return Status::kOk;
}

FeatureParams Database::feature_params() const noexcept {
  FeatureParams f;
  if (params_ == nullptr) return f;  // not open: the defaults
  f.cloud_voxel = params_->cloud_voxel;
  f.normal_radius = params_->normal_radius;
  f.basis_spacing = params_->basis_spacing;
  f.support_radius = params_->support_radius;
  f.bins_alpha = params_->bins_alpha;
  f.bins_beta = params_->bins_beta;
  f.support_angle_deg = params_->support_angle_deg;
  f.spin_quant_scale = params_->spin_quant_scale;
  return f;
}

int32_t Database::find_model(const char* name) const noexcept {
  if (models_ == nullptr || name == nullptr) return -1;
  for (uint32_t i = 0; i < params_->model_count && i < kMaxModels; ++i) {
    if (name_equals(models_[i].name, name)) return static_cast<int32_t>(i);
  }
  return -1;
}

}  // namespace spinhash
