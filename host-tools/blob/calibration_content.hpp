// The Calibration section of a blob as host vectors (blob_format.hpp,
// docs/blob-format.md 5.8).
#pragma once
#include <cstdint>
#include <vector>

#include "spinhash/blob_format.hpp"

namespace spinhash {
namespace host {

struct CalibrationContent {
  blob::CalibrationHeader header{};
  std::vector<blob::CalibrationPass> passes;  // header.pass_count
  std::vector<blob::CalibrationCell> cells;   // pass_count x level_count x band_count, pass-major
};

// A section without a fitted table: one pass (full) decided by the
// recognizer's priors, one density band.
CalibrationContent priors_calibration();

// Bytes of the section for `c`'s header counts.
uint64_t calibration_bytes(const blob::CalibrationHeader& h);

}  // namespace host
}  // namespace spinhash
