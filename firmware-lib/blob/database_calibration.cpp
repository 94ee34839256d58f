// Last stage of Database::open: the Calibration section (docs/blob-format.md
// 5.8). Its size follows from its own header's counts, so the header is
// checked first; then the density bands, the pass records and the cells,
// each threshold against its level's denser bands.
#include <cmath>

#include "blob/database_checks.hpp"
#include "spinhash/calibration.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace blob_check {
namespace {

bool unit_interval(float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; }
bool valid_target(float t) { return std::isfinite(t) && t > 0.0f && t <= 1.0f; }

uint64_t payload_bytes(const blob::CalibrationHeader& h) {
  const uint64_t cells = static_cast<uint64_t>(h.pass_count) * h.level_count * h.band_count;
  return sizeof(blob::CalibrationHeader) + h.pass_count * sizeof(blob::CalibrationPass) +
         cells * sizeof(blob::CalibrationCell);
}

Status check_counts(const blob::CalibrationHeader& h, uint64_t size) {
  if (h.level_count != kCalibratedLevels || h.pass_count < 1u || h.pass_count > blob::kMaxCalibrationPasses ||
      h.band_count < 1u || h.band_count > blob::kMaxDensityBands)
    return Status::kBlobBadCalibration;
  return payload_bytes(h) == size ? Status::kOk : Status::kBlobSizeMismatch;
}

// Band edges: from 0, finite, strictly increasing; the unused ones zero.
Status check_bands(const blob::CalibrationHeader& h) {
  if (!all_zero(h.reserved, sizeof(h.reserved))) return Status::kBlobNotZeroed;
  if (h.clutter > blob::kClutterVehicleSized) return Status::kBlobBadCalibration;
  for (uint32_t b = h.band_count; b < blob::kMaxDensityBands; ++b)
    if (h.band_min_density[b] != 0.0f) return Status::kBlobNotZeroed;
  if (!valid_target(h.target_precision)) return Status::kBlobBadCalibration;
  if (h.band_min_density[0] != 0.0f) return Status::kBlobBadCalibration;
  for (uint32_t b = 1; b < h.band_count; ++b) {
    const float v = h.band_min_density[b];
    if (!std::isfinite(v) || !(v > h.band_min_density[b - 1u])) return Status::kBlobBadCalibration;
  }
  return Status::kOk;
}

Status check_pass(const blob::CalibrationPass& p, uint32_t index) {
  if (p.pass != index || p.pass >= kAnswerPassCount) return Status::kBlobBadCalibration;
  if (p.source == blob::kSourcePriors)
    return p.runs == 0u && p.target_precision == 0.0f ? Status::kOk : Status::kBlobBadCalibration;
  if (p.source != blob::kSourceFitted) return Status::kBlobBadCalibration;
  return p.target_precision == 0.0f || valid_target(p.target_precision) ? Status::kOk
                                                                        : Status::kBlobBadCalibration;
}

// One cell of a fitted table on its own.
bool fitted_cell_ok(const blob::CalibrationCell& c, float target) {
  if (!std::isfinite(c.threshold) || !unit_interval(c.precision) || !unit_interval(c.recall)) return false;
  if (static_cast<uint64_t>(c.flagged) > static_cast<uint64_t>(c.positives) + c.negatives) return false;
  if (c.state == blob::kCellFitted) return c.precision >= target;
  // Never confident: nothing flagged, nothing expected.
  return (c.state == blob::kCellTooFew || c.state == blob::kCellUnreachable) && c.threshold == 0.0f &&
         c.precision == 0.0f && c.recall == 0.0f && c.flagged == 0u;
}

// One level's cells, sparsest band first: each on its own, then the order:
// once a band is confident at some threshold, every denser band is too, at
// the same or a lower one.
Status check_level(const blob::CalibrationCell* cells, uint32_t bands, bool fitted, float target) {
  bool seen_fitted = false;
  float previous = 0.0f;
  for (uint32_t b = 0; b < bands; ++b) {
    const blob::CalibrationCell& c = cells[b];
    if (c.reserved != 0u) return Status::kBlobNotZeroed;
    if (!fitted) {
      if (!all_zero(reinterpret_cast<const uint8_t*>(&c), sizeof(c))) return Status::kBlobBadCalibration;
      continue;
    }
    if (!fitted_cell_ok(c, target)) return Status::kBlobBadCalibration;
    if (c.state == blob::kCellFitted) {
      if (seen_fitted && c.threshold > previous) return Status::kBlobBadCalibration;
      seen_fitted = true;
      previous = c.threshold;
    } else if (seen_fitted) {
      return Status::kBlobBadCalibration;
    }
  }
  return Status::kOk;
}

}  // namespace

Status check_calibration(const Sections& s) {
  const uint64_t size = s.size[blob::kCalibration];
  if (size < sizeof(blob::CalibrationHeader)) return Status::kBlobSizeMismatch;
  const uint8_t* payload = s.data[blob::kCalibration];
  const blob::CalibrationHeader& h = *reinterpret_cast<const blob::CalibrationHeader*>(payload);
  Status st = check_counts(h, size);
  if (st != Status::kOk) return st;
  st = check_bands(h);
  if (st != Status::kOk) return st;
  const blob::CalibrationPass* passes =
      reinterpret_cast<const blob::CalibrationPass*>(payload + sizeof(blob::CalibrationHeader));
  const blob::CalibrationCell* cells = reinterpret_cast<const blob::CalibrationCell*>(passes + h.pass_count);
  for (uint32_t p = 0; p < h.pass_count && p < blob::kMaxCalibrationPasses; ++p) {
    st = check_pass(passes[p], p);
    if (st != Status::kOk) return st;
    for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
      st = check_level(cells + (static_cast<size_t>(p) * kCalibratedLevels + l) * h.band_count, h.band_count,
                       passes[p].source == blob::kSourceFitted, blob::pass_target_precision(h, passes[p]));
      if (st != Status::kOk) return st;
    }
  }
  return Status::kOk;
}

}  // namespace blob_check
}  // namespace spinhash
