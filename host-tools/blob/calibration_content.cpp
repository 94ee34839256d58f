#include "blob/calibration_content.hpp"

#include "spinhash/calibration.hpp"

namespace spinhash {
namespace host {

CalibrationContent priors_calibration() {
  CalibrationContent c;
  c.header.pass_count = 1;
  c.header.level_count = kCalibratedLevels;
  c.header.band_count = 1;
  c.header.target_precision = 1.0f;  // no fit: nothing was targeted below certainty
  c.passes.push_back(
      blob::CalibrationPass{static_cast<uint32_t>(AnswerPass::kFull), blob::kSourcePriors, 0u, 0.0f});
  c.cells.assign(kCalibratedLevels, blob::CalibrationCell{});
  return c;
}

uint64_t calibration_bytes(const blob::CalibrationHeader& h) {
  const uint64_t cells = static_cast<uint64_t>(h.pass_count) * h.level_count * h.band_count;
  return sizeof(blob::CalibrationHeader) +
         static_cast<uint64_t>(h.pass_count) * sizeof(blob::CalibrationPass) +
         cells * sizeof(blob::CalibrationCell);
}

}  // namespace host
}  // namespace spinhash
