// Stage 3 of Database::open: the Params section. Counts are range-checked
// first, then every section size is recomputed from them in 64-bit arithmetic
// (a 32-bit product could wrap to a small, matching size), then the floats.
#include <cmath>

#include "blob/database_checks.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace blob_check {
namespace {

constexpr uint32_t kMaxLshBuckets = 1u << 28;
constexpr float kMaxSupportAngleDeg = 360.0f;

bool in_range(uint32_t v, uint32_t lo, uint32_t hi) { return v >= lo && v <= hi; }
bool is_power_of_two(uint32_t v) { return v != 0u && (v & (v - 1u)) == 0u; }
bool positive_finite(float v) { return std::isfinite(v) && v > 0.0f; }

Status check_counts(const blob::Params& p) {
  const bool ok = in_range(p.model_count, 1u, kMaxModels) && in_range(p.feature_count, 1u, kMaxFeatures) &&
                  in_range(p.bins_alpha, 1u, kMaxSpinBinsPerAxis) &&
                  in_range(p.bins_beta, 1u, kMaxSpinBinsPerAxis) &&
                  in_range(p.lsh_tables, 1u, kMaxLshTables) && in_range(p.lsh_bits, 1u, kMaxLshBits) &&
                  in_range(p.lsh_buckets, 1u, kMaxLshBuckets) && p.grid_offset_count >= 1u;
  if (!ok) return Status::kBlobCountOverflow;
  if (!is_power_of_two(p.lsh_buckets)) return Status::kBlobBadParameter;
  return Status::kOk;
}

// Expected payload of one section: element bytes * a * b.
struct SizeRule {
  uint32_t id;
  uint64_t element_bytes;
  uint64_t a;
  uint64_t b;
};

Status check_sizes(const blob::Params& p, const Sections& s) {
  const uint64_t n = p.feature_count;
  const uint64_t tables = p.lsh_tables;
  const SizeRule rules[] = {
      {blob::kModels, sizeof(blob::ModelRecord), p.model_count, 1u},
      {blob::kFeatPositions, sizeof(float) * 3u, n, 1u},
      {blob::kFeatNormals, sizeof(int16_t) * 3u, n, 1u},
      {blob::kFeatModels, sizeof(uint16_t), n, 1u},
      {blob::kFeatSpins, 1u, static_cast<uint64_t>(p.bins_alpha) * p.bins_beta, n},
      {blob::kGridOffsets, sizeof(uint32_t), p.grid_offset_count, 1u},
      {blob::kLshBits, sizeof(blob::LshBit), tables, p.lsh_bits},
      {blob::kLshOffsets, sizeof(uint32_t), tables, static_cast<uint64_t>(p.lsh_buckets) + 1u},
      {blob::kLshEntries, sizeof(uint32_t), tables, n},
      {blob::kNearestField, sizeof(uint16_t), p.field_entry_count, 1u},
  };
  for (const SizeRule& r : rules) {
    uint64_t elements = 0;
    uint64_t bytes = 0;
    if (!mul_u64(r.a, r.b, &elements) || !mul_u64(elements, r.element_bytes, &bytes)) {
      return Status::kBlobCountOverflow;
    }
    if (bytes != s.size[r.id]) return Status::kBlobSizeMismatch;
  }
  return Status::kOk;
}

// The nearest-feature field is wholly absent (all zero) or wholly described.
bool field_ok(const blob::Params& p) {
  if (p.field_entry_count == 0u) return p.field_slots == 0u && p.field_cell == 0.0f && p.field_reach == 0.0f;
  return in_range(p.field_slots, 1u, kMaxFieldSlots) && positive_finite(p.field_cell) &&
         std::isfinite(p.field_reach) && p.field_reach >= 0.0f;
}

Status check_floats(const blob::Params& p) {
  const bool ok = positive_finite(p.cloud_voxel) && positive_finite(p.normal_radius) &&
                  positive_finite(p.basis_spacing) && positive_finite(p.support_radius) &&
                  positive_finite(p.support_angle_deg) && p.support_angle_deg <= kMaxSupportAngleDeg &&
                  positive_finite(p.spin_quant_scale) && std::isfinite(p.lsh_dc) && p.lsh_dc >= 0.0f &&
                  positive_finite(p.grid_cell);
  return ok && field_ok(p) ? Status::kOk : Status::kBlobBadParameter;
}

}  // namespace

Status check_params(const blob::Header& header, const Sections& s) {
  if (s.size[blob::kParams] != sizeof(blob::Params)) return Status::kBlobSizeMismatch;
  const blob::Params& p = params_of(s);
  Status st = check_counts(p);
  if (st != Status::kOk) return st;
  st = check_sizes(p, s);
  if (st != Status::kOk) return st;
  st = check_floats(p);
  if (st != Status::kOk) return st;
  if (fnv1a64(&p, sizeof(p)) != header.config_fingerprint) return Status::kBlobBadParameter;
  return Status::kOk;
}

}  // namespace blob_check
}  // namespace spinhash
