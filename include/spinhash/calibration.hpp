// Answer levels (answer_levels.h is the list) and the database's
// calibration of their flags: a read-only view of the blob's Calibration
// section (docs/blob-format.md), validated by Database::open.
#pragma once
#include <cstdint>

#include "spinhash/answer_levels.h"
#include "spinhash/blob_format.hpp"

namespace spinhash {

enum class AnswerLevel : uint8_t {
#define SPINHASH_LEVEL_ENUM(id, Name, name, help) k##Name = id,
  SPINHASH_ANSWER_LEVELS(SPINHASH_LEVEL_ENUM)
#undef SPINHASH_LEVEL_ENUM
};
constexpr uint32_t kAnswerLevelCount = SPINHASH_ANSWER_LEVEL_COUNT;
// Levels with a flag of their own: ids 1 .. kCalibratedLevels (vehicle ..
// model, coarse to specific); a table's cells run over them in id order.
constexpr uint32_t kCalibratedLevels = SPINHASH_CALIBRATED_LEVELS;
static_assert(kAnswerLevelCount == kCalibratedLevels + 1u, "every level but none is calibrated");

enum class AnswerPass : uint8_t {
#define SPINHASH_PASS_ENUM(id, Name, name, help) k##Name = id,
  SPINHASH_CALIBRATION_PASSES(SPINHASH_PASS_ENUM)
#undef SPINHASH_PASS_ENUM
};
constexpr uint32_t kAnswerPassCount = SPINHASH_CALIBRATION_PASS_COUNT;
static_assert(kAnswerPassCount <= blob::kMaxCalibrationPasses, "every pass fits the section");

// "vehicle", ...; "unknown" outside the list.
const char* answer_level_name(uint32_t id) noexcept;
// "full", ...; "unknown" outside the list.
const char* answer_pass_name(uint32_t id) noexcept;
// The level named `name`, or false.
bool parse_answer_level(const char* name, AnswerLevel* out) noexcept;

// Index of a calibrated level in a table (0 for vehicle .. 3 for model).
constexpr uint32_t level_index(AnswerLevel level) { return static_cast<uint32_t>(level) - 1u; }

// The Calibration section of an open database. Default-constructed (no
// database): no table, every pass decided by the priors.
class Calibration {
 public:
  Calibration() = default;
  // `payload` validated by Database::open (blob/database_calibration.cpp).
  explicit Calibration(const uint8_t* payload) noexcept;

  bool present() const noexcept { return header_ != nullptr; }
  const blob::CalibrationHeader& header() const noexcept { return *header_; }
  uint32_t pass_count() const noexcept { return header_ != nullptr ? header_->pass_count : 0u; }
  uint32_t band_count() const noexcept { return header_ != nullptr ? header_->band_count : 0u; }
  const blob::CalibrationPass& pass_record(uint32_t index) const noexcept { return passes_[index]; }
  // Lower edge of band b, points per m^2 (band 0 starts at 0; the last is open above).
  float band_min_density(uint32_t band) const noexcept { return header_->band_min_density[band]; }
  // The band holding `density` (RecognitionStats::scan_density); 0 for a
  // density below every edge or not a number.
  uint32_t band_of(float density) const noexcept;

  // The pass has a fitted table (else the recognizer's priors decide it).
  bool fitted(AnswerPass pass) const noexcept;
  // The precision the pass's table was fitted to: its record's own, else
  // the header's (0 without the pass).
  float target_precision(AnswerPass pass) const noexcept;
  // The cell of (pass, level, band), or null: no such pass in the section,
  // level none, or band out of range.
  const blob::CalibrationCell* cell(AnswerPass pass, AnswerLevel level, uint32_t band) const noexcept;
  // The fitted decision: `evidence` reaches the threshold of its density's
  // band (false in a band that is never confident). Only meaningful when
  // fitted(pass).
  bool confident(AnswerPass pass, AnswerLevel level, float evidence, float density) const noexcept;

 private:
  const blob::CalibrationHeader* header_ = nullptr;
  const blob::CalibrationPass* passes_ = nullptr;
  const blob::CalibrationCell* cells_ = nullptr;
};

}  // namespace spinhash
