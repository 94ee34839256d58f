#include "calib/calibration_check.hpp"

#include <algorithm>
#include <cmath>

namespace spinhash::calib {
namespace {

constexpr double kZ = 3.29;  // two-sided 99.9 %: a sound calibration fails one level in a thousand

struct Interval {
  double low = 0.0, high = 1.0;
};

// Wilson score interval of a share p observed on n (effective) runs.
Interval wilson(double p, double n) {
  if (!(n > 0.0)) return Interval{};
  const double z2 = kZ * kZ, centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = kZ * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n)) / (1.0 + z2 / n);
  // At a share of 0 or 1 the interval's end is exactly that share (centre
  // and half cancel there, but not always to the last bit).
  return Interval{p <= 0.0 ? 0.0 : std::max(0.0, centre - half),
                  p >= 1.0 ? 1.0 : std::min(1.0, centre + half)};
}

// Sums of weights, for a share and its effective number of runs.
struct Tally {
  double hit = 0.0, all = 0.0, all2 = 0.0, expected = 0.0;
  void add(double w, bool h, double e) {
    hit += h ? w : 0.0;
    all += w;
    all2 += w * w;
    expected += w * e;
  }
  double share() const { return all > 0.0 ? hit / all : 0.0; }
  double expectation() const { return all > 0.0 ? expected / all : 0.0; }
  double effective() const { return all2 > 0.0 ? all * all / all2 : 0.0; }
};

}  // namespace

std::vector<LevelCheck> check_calibration(const Calibration& c, AnswerPass pass,
                                          const std::vector<host::CalibrationRun>& runs) {
  double known = 0.0, unknown = 0.0;
  for (const host::CalibrationRun& r : runs) {
    if (r.pass != pass) continue;
    known += r.kind == host::RunKind::kKnown ? 1.0 : 0.0;
    unknown += r.kind == host::RunKind::kUnknown ? 1.0 : 0.0;
  }
  const double unknown_weight = known > 0.0 && unknown > 0.0 ? known / unknown : 1.0;
  std::vector<LevelCheck> out;
  for (uint32_t l = 1; l <= kCalibratedLevels; ++l) {
    const AnswerLevel level = static_cast<AnswerLevel>(l);
    LevelCheck k;
    k.pass = pass;
    k.level = level;
    Tally precision, recall;
    for (const host::CalibrationRun& r : runs) {
      if (r.pass != pass) continue;
      const blob::CalibrationCell* cell = c.cell(pass, level, c.band_of(r.density));
      if (cell == nullptr) continue;
      const double w = r.kind == host::RunKind::kUnknown ? unknown_weight : 1.0;
      const float e = r.evidence[l - 1u];
      const bool right = r.right[l - 1u];
      const bool flagged = c.confident(pass, level, e, r.density);
      ++k.runs;
      if (flagged) {
        ++k.flagged;
        k.wrong += right ? 0u : 1u;
        precision.add(w, right, cell->precision);
      }
      if (right) recall.add(w, flagged, cell->state == blob::kCellFitted ? cell->recall : 0.0);
    }
    k.expected_precision = precision.expectation();
    k.observed_precision = precision.share();
    k.expected_recall = recall.expectation();
    k.observed_recall = recall.share();
    const Interval p = wilson(k.observed_precision, precision.effective());
    const Interval q = wilson(k.observed_recall, recall.effective());
    k.precision_low = p.low, k.precision_high = p.high;
    k.recall_low = q.low, k.recall_high = q.high;
    k.agrees = (k.flagged == 0u || k.expected_precision <= p.high) &&
               (recall.all == 0.0 || (k.expected_recall >= q.low && k.expected_recall <= q.high));
    out.push_back(k);
  }
  return out;
}

}  // namespace spinhash::calib
