// The fit of the answer levels' thresholds (docs/blob-format.md 5.8) from
// calibration runs: simulated scans of the database's own models, each
// recognised with its model in the database (known) and left out
// (unknown), and scans of clutter. Pure: the runs come from
// host-tools/calib/.
//
// Per level and band of scan density, the threshold is the smallest
// evidence at which the runs at or above it are right with at least the
// target precision, and at which at most (1 - target) / 2 of the outsiders
// are flagged: at the model level the unknown vehicles and the clutter,
// at every other level the clutter. At the group and class levels,
// precision weighs the unknown runs so that they count as much as the
// known ones together (the fit expects half the vehicles met to be in the
// database, whatever share of its models was left out); at the model level
// it leaves them out (none of them can be named right: the outsider rate
// bounds them). Thresholds never increase with density: where a denser band
// would need more evidence than a sparser one, the two are pooled and fitted
// together. A band with fewer than min_band_runs runs, or whose runs reach
// the target at no threshold, is never confident.
//
// The agree pass's runs carry the first pass's evidence and, per level,
// whether stopping after the first pass loses no right answer there (wrong
// only when the full pass names the truth and the first pass does not): its table
// is fitted the same way to agree_precision, over known, unknown and
// clutter runs alike (no outsiders; the unknown runs weighed as at the
// group and class levels).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "blob/calibration_content.hpp"
#include "spinhash/calibration.hpp"

namespace spinhash {
namespace host {

enum class RunKind : uint8_t {
  kKnown = 0,    // the scanned model is in the database
  kUnknown = 1,  // the database was built without it
  kClutter = 2,  // a tree, wall, crate or building
};

struct CalibrationRun {
  AnswerPass pass = AnswerPass::kFull;  // the pass whose answer this is (agree: the first pass's)
  RunKind kind = RunKind::kKnown;
  float density = 0.0f;                    // RecognitionStats::scan_density
  float evidence[kCalibratedLevels] = {};  // Result::levels[l].evidence
  bool right[kCalibratedLevels] = {};  // the answer at that level names the truth (agree: loses no right one)
};

struct FitOptions {
  float target_precision = 0.99f;
  // The agree table's (the cascade's stop): stopping early loses a right
  // answer the full pass would give on at most about 1 - agree_precision of
  // the queries it stops, so it stays within the accuracy target of the full pass.
  float agree_precision = 0.995f;
  // Lower edges of the density bands, points per m^2: 0 first, increasing.
  std::vector<float> band_edges{0.0f, 15.0f, 30.0f, 60.0f, 120.0f, 240.0f};
  uint32_t min_band_runs = 0;  // 0: ceil(1 / (1 - target)), the runs one wrong answer in a hundred needs
};

// What the fit drew on, for the section's header.
struct FitProvenance {
  uint32_t scans_per_model = 0;
  uint32_t scans_per_left_out = 0;
  uint32_t models_left_out = 0;
  uint32_t clutter_scans = 0;
  uint64_t seed = 0;
  uint32_t clutter = blob::kClutterTiles;  // blob::CalibrationClutter
};

// A section with a fitted table for the full pass and every other pass the
// runs hold (in id order, each fitted from its own runs alone, the agree
// pass to agree_precision, which its record keeps; a pass before the last
// without runs is left to its priors); false with *error for bad options
// or a run of an unknown pass.
bool fit_calibration(const std::vector<CalibrationRun>& runs, const FitOptions& options,
                     const FitProvenance& provenance, CalibrationContent* out, std::string* error);

// The least runs a band needs for `target` (FitOptions::min_band_runs 0).
uint32_t default_min_band_runs(float target);

}  // namespace host
}  // namespace spinhash
