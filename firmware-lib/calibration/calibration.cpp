// The answer levels' and passes' names, and the view of the Calibration
// section (calibration.hpp).
#include "spinhash/calibration.hpp"

namespace spinhash {
namespace {

#define SPINHASH_LEVEL_NAME(id, Name, name, help) name,
constexpr const char* kLevelNames[] = {SPINHASH_ANSWER_LEVELS(SPINHASH_LEVEL_NAME)};
#undef SPINHASH_LEVEL_NAME
#define SPINHASH_LEVEL_ID(id, Name, name, help) id,
constexpr uint32_t kLevelIds[] = {SPINHASH_ANSWER_LEVELS(SPINHASH_LEVEL_ID)};
#undef SPINHASH_LEVEL_ID
#define SPINHASH_PASS_NAME(id, Name, name, help) name,
constexpr const char* kPassNames[] = {SPINHASH_CALIBRATION_PASSES(SPINHASH_PASS_NAME)};
#undef SPINHASH_PASS_NAME
#define SPINHASH_PASS_ID(id, Name, name, help) id,
constexpr uint32_t kPassIds[] = {SPINHASH_CALIBRATION_PASSES(SPINHASH_PASS_ID)};
#undef SPINHASH_PASS_ID
static_assert(sizeof(kLevelNames) / sizeof(kLevelNames[0]) == kAnswerLevelCount,
              "SPINHASH_ANSWER_LEVEL_COUNT matches SPINHASH_ANSWER_LEVELS");
static_assert(sizeof(kPassNames) / sizeof(kPassNames[0]) == kAnswerPassCount,
              "SPINHASH_CALIBRATION_PASS_COUNT matches SPINHASH_CALIBRATION_PASSES");

template <uint32_t N>
constexpr bool ids_are_positions(const uint32_t (&ids)[N]) {
  for (uint32_t k = 0; k < N; ++k)
    if (ids[k] != k) return false;
  return true;
}
static_assert(ids_are_positions(kLevelIds), "level ids run 0, 1, 2, ... in list order");
static_assert(ids_are_positions(kPassIds), "pass ids run 0, 1, 2, ... in list order");

constexpr uint32_t kMaxLevelNameBytes = 16;  // longer names match nothing

bool same_name(const char* a, const char* b) {
  for (uint32_t k = 0; k < kMaxLevelNameBytes; ++k) {
    if (a[k] != b[k]) return false;
    if (a[k] == '\0') return true;
  }
  return false;
}

}  // namespace

const char* answer_level_name(uint32_t id) noexcept {
  return id < kAnswerLevelCount ? kLevelNames[id] : "unknown";
}

const char* answer_pass_name(uint32_t id) noexcept {
  return id < kAnswerPassCount ? kPassNames[id] : "unknown";
}

bool parse_answer_level(const char* name, AnswerLevel* out) noexcept {
  if (name == nullptr) return false;
  for (uint32_t id = 0; id < kAnswerLevelCount; ++id) {
    if (!same_name(name, kLevelNames[id])) continue;
    if (out != nullptr) *out = static_cast<AnswerLevel>(id);
    return true;
  }
  return false;
}

Calibration::Calibration(const uint8_t* payload) noexcept {
  if (payload == nullptr) return;
  header_ = reinterpret_cast<const blob::CalibrationHeader*>(payload);
  passes_ = reinterpret_cast<const blob::CalibrationPass*>(payload + sizeof(blob::CalibrationHeader));
  cells_ = reinterpret_cast<const blob::CalibrationCell*>(
      payload + sizeof(blob::CalibrationHeader) + header_->pass_count * sizeof(blob::CalibrationPass));
}

uint32_t Calibration::band_of(float density) const noexcept {
  uint32_t band = 0;
  for (uint32_t b = 1; b < band_count() && b < blob::kMaxDensityBands; ++b)
    if (density >= header_->band_min_density[b]) band = b;  // false for NaN
  return band;
}

bool Calibration::fitted(AnswerPass pass) const noexcept {
  const uint32_t p = static_cast<uint32_t>(pass);
  return p < pass_count() && passes_[p].source == blob::kSourceFitted;
}

float Calibration::target_precision(AnswerPass pass) const noexcept {
  const uint32_t p = static_cast<uint32_t>(pass);
  if (p >= pass_count()) return 0.0f;
  return blob::pass_target_precision(*header_, passes_[p]);
}

const blob::CalibrationCell* Calibration::cell(AnswerPass pass, AnswerLevel level,
                                               uint32_t band) const noexcept {
  const uint32_t p = static_cast<uint32_t>(pass);
  if (p >= pass_count() || level == AnswerLevel::kNone || band >= band_count()) return nullptr;
  const uint32_t l = level_index(level);
  if (l >= kCalibratedLevels) return nullptr;
  return cells_ + (static_cast<size_t>(p) * kCalibratedLevels + l) * header_->band_count + band;
}

bool Calibration::confident(AnswerPass pass, AnswerLevel level, float evidence,
                            float density) const noexcept {
  const blob::CalibrationCell* c = cell(pass, level, band_of(density));
  return c != nullptr && c->state == blob::kCellFitted && evidence >= c->threshold;
}

}  // namespace spinhash
