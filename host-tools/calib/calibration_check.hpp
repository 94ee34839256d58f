// `spinhash verify`'s check of a fitted calibration: new calibration runs
// (other seeds than the build's) against the precision and recall the
// stored cells expect, per level over all bands, within sampling error.
#pragma once
#include <vector>

#include "db/calibration_fit.hpp"
#include "spinhash/calibration.hpp"

namespace spinhash::calib {

struct LevelCheck {
  AnswerPass pass = AnswerPass::kFull;
  AnswerLevel level = AnswerLevel::kNone;
  uint32_t runs = 0;     // runs with this level's answer right or wrong
  uint32_t flagged = 0;  // of them, at or above their band's threshold
  uint32_t wrong = 0;    // of those, wrong
  // Weighted as the fit weighs (unknown runs count as much as the known
  // ones together): what the cells expect of these runs and what they gave.
  double expected_precision = 0.0, observed_precision = 0.0;
  double expected_recall = 0.0, observed_recall = 0.0;
  // 99.9 % (Wilson, on the runs' effective number) intervals of the observed shares.
  double precision_low = 0.0, precision_high = 1.0, recall_low = 0.0, recall_high = 1.0;
  // The expected precision is not above the observed's interval, and the
  // expected recall lies in the observed's (a level that flagged nothing
  // agrees when the cells expected next to nothing).
  bool agrees = true;
};

// Per calibrated level of `pass` (fitted), the check of `runs` of that pass
// (the others are passed over).
std::vector<LevelCheck> check_calibration(const Calibration& c, AnswerPass pass,
                                          const std::vector<host::CalibrationRun>& runs);

}  // namespace spinhash::calib
