#include "db/calibration_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spinhash {
namespace host {
namespace {

constexpr float kLargestThreshold = std::numeric_limits<float>::max();  // flags only unopposed answers

// One run as one level sees it.
struct Sample {
  float evidence;
  bool right;
  bool outsider;  // counts against the outsider rate
  double weight;  // in precision and recall
};

// What a threshold gives on a set of samples.
struct Fit {
  bool enough = false;     // the runs reach min_band_runs
  bool reached = false;    // some threshold meets both targets
  float threshold = 0.0f;  // the smallest that does
  double precision = 0.0, recall = 0.0;
};

// The agree table's question (would stopping after the first pass lose a
// right answer the full pass gives?) has an answer on every run: it has no
// outsiders.
bool is_outsider(AnswerPass pass, RunKind kind, AnswerLevel level) {
  if (pass == AnswerPass::kAgree) return false;
  return kind == RunKind::kClutter || (level == AnswerLevel::kModel && kind == RunKind::kUnknown);
}

// The target as the decimal it was given as: 0.99f is a little over 0.99,
// and would refuse exactly 99 right of 100.
double decimal(float target) { return std::round(static_cast<double>(target) * 1e6) / 1e6; }

// Smallest threshold over `s` (sorted by evidence, highest first) whose
// flagged samples are right with `target` precision and flag at most
// (1 - target) / 2 of the outsiders.
Fit fit_samples(std::vector<Sample>& s, float target_f, uint32_t min_runs) {
  const double target = decimal(target_f);
  Fit fit;
  fit.enough = s.size() >= min_runs;
  if (!fit.enough) return fit;
  std::sort(s.begin(), s.end(), [](const Sample& a, const Sample& b) { return a.evidence > b.evidence; });
  double right_total = 0.0;
  uint64_t outsiders = 0;
  for (const Sample& x : s) {
    right_total += x.right ? x.weight : 0.0;
    outsiders += x.outsider ? 1u : 0u;
  }
  const double outsider_share = 0.5 * (1.0 - target);
  double right = 0.0, flagged = 0.0;
  uint64_t outsiders_flagged = 0;
  for (size_t i = 0; i < s.size();) {
    const float v = s[i].evidence;
    if (!(v > -std::numeric_limits<float>::infinity())) break;  // failed prerequisites: never flagged
    for (; i < s.size() && s[i].evidence == v; ++i) {           // ties go together
      right += s[i].right ? s[i].weight : 0.0;
      flagged += s[i].weight;
      outsiders_flagged += s[i].outsider ? 1u : 0u;
    }
    if (static_cast<double>(outsiders_flagged) > outsider_share * static_cast<double>(outsiders)) break;
    const double precision = flagged > 0.0 ? right / flagged : 0.0;
    if (precision >= target) {
      fit.reached = true;
      fit.threshold = std::min(v, kLargestThreshold);
      fit.precision = precision;
      fit.recall = right_total > 0.0 ? right / right_total : 0.0;
    }
  }
  return fit;
}

// A run of adjacent bands fitted together.
struct Block {
  uint32_t first = 0, last = 0;  // bands, inclusive
  Fit fit;
};

// Thresholds of adjacent blocks in order: the denser needs no more evidence
// (a band never confident needs infinitely much).
bool ordered(const Fit& sparser, const Fit& denser) {
  if (!(sparser.enough && sparser.reached)) return true;
  return denser.enough && denser.reached && denser.threshold <= sparser.threshold;
}

class LevelFitter {
 public:
  LevelFitter(const std::vector<CalibrationRun>& runs, const std::vector<float>& edges, AnswerPass pass,
              AnswerLevel level, double unknown_weight, float target, uint32_t min_runs)
      : runs_(runs),
        edges_(edges),
        pass_(pass),
        level_(level),
        unknown_weight_(unknown_weight),
        target_(target),
        min_runs_(min_runs) {}

  // Fits every band, pooling adjacent ones until the thresholds never increase with density.
  std::vector<Block> fit() {
    std::vector<Block> blocks;
    for (uint32_t b = 0; b < edges_.size(); ++b) blocks.push_back(fit_block(b, b));
    for (size_t i = 0; i + 1 < blocks.size();) {
      if (ordered(blocks[i].fit, blocks[i + 1].fit)) {
        ++i;
        continue;
      }
      blocks[i] = fit_block(blocks[i].first, blocks[i + 1].last);
      blocks.erase(blocks.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      i = i > 0 ? i - 1 : 0;  // the pooled block may now break the order with the one before
    }
    return blocks;
  }

  uint32_t band_of(float density) const {
    uint32_t band = 0;
    for (uint32_t b = 1; b < edges_.size(); ++b)
      if (density >= edges_[b]) band = b;
    return band;
  }

  // An unknown vehicle is never right at the model level: there the
  // outsider rate bounds it, and precision is that of the answers whose
  // model could be named. Elsewhere, and at every level of the agree table
  // (where a left-out vehicle loses nothing by the stop), it weighs unknown_weight_.
  double weight(RunKind kind) const {
    if (kind != RunKind::kUnknown) return 1.0;
    return level_ == AnswerLevel::kModel && pass_ != AnswerPass::kAgree ? 0.0 : unknown_weight_;
  }

  std::vector<Sample> samples(uint32_t first, uint32_t last) const {
    const uint32_t l = level_index(level_);
    std::vector<Sample> s;
    for (const CalibrationRun& r : runs_) {
      const uint32_t b = band_of(r.density);
      if (b < first || b > last) continue;
      s.push_back(Sample{r.evidence[l], r.right[l], is_outsider(pass_, r.kind, level_), weight(r.kind)});
    }
    return s;
  }

 private:
  Block fit_block(uint32_t first, uint32_t last) const {
    std::vector<Sample> s = samples(first, last);
    return Block{first, last, fit_samples(s, target_, min_runs_)};
  }

  const std::vector<CalibrationRun>& runs_;
  const std::vector<float>& edges_;
  AnswerPass pass_;
  AnswerLevel level_;
  double unknown_weight_;
  float target_;
  uint32_t min_runs_;
};

// The cell of one band under its block's fit.
blob::CalibrationCell make_cell(const std::vector<Sample>& band, const Fit& fit) {
  blob::CalibrationCell c{};
  for (const Sample& x : band) {
    (x.right ? c.positives : c.negatives) += 1u;
  }
  if (!fit.enough) {
    c.state = blob::kCellTooFew;
  } else if (!fit.reached) {
    c.state = blob::kCellUnreachable;
  } else {
    c.state = blob::kCellFitted;
    c.threshold = fit.threshold;
    c.precision = static_cast<float>(fit.precision);
    c.recall = static_cast<float>(fit.recall);
    for (const Sample& x : band) c.flagged += x.evidence >= fit.threshold ? 1u : 0u;
  }
  return c;
}

bool check_options(const FitOptions& o, std::string* error) {
  if (!(o.target_precision > 0.0f && o.target_precision <= 1.0f) ||
      !(o.agree_precision > 0.0f && o.agree_precision <= 1.0f)) {
    *error = "target and agree precision must be in (0, 1]";
    return false;
  }
  if (o.band_edges.empty() || o.band_edges.size() > blob::kMaxDensityBands || o.band_edges[0] != 0.0f) {
    *error = "density bands: 1 to " + std::to_string(blob::kMaxDensityBands) + " lower edges, the first 0";
    return false;
  }
  for (size_t b = 1; b < o.band_edges.size(); ++b)
    if (!std::isfinite(o.band_edges[b]) || !(o.band_edges[b] > o.band_edges[b - 1])) {
      *error = "density band edges must be finite and increasing";
      return false;
    }
  return true;
}

}  // namespace

uint32_t default_min_band_runs(float target) {
  if (!(target < 1.0f)) return std::numeric_limits<uint32_t>::max();
  return static_cast<uint32_t>(std::ceil(1.0 / (1.0 - decimal(target)) - 1e-9));
}

bool fit_calibration(const std::vector<CalibrationRun>& runs, const FitOptions& options,
                     const FitProvenance& provenance, CalibrationContent* out, std::string* error) {
  if (!check_options(options, error)) return false;
  // The runs of each pass; the passes fitted: the full pass and every later
  // pass up to the last with runs (a pass between without runs keeps its
  // priors: its record says so and its cells are empty).
  std::vector<std::vector<CalibrationRun>> by_pass(kAnswerPassCount);
  for (const CalibrationRun& r : runs) {
    const uint32_t p = static_cast<uint32_t>(r.pass);
    if (p >= kAnswerPassCount) {
      *error = "calibration run of an unknown pass";
      return false;
    }
    by_pass[p].push_back(r);
  }
  uint32_t pass_count = 1;  // the full pass's table, fitted even from no runs (never confident)
  for (uint32_t p = 1; p < kAnswerPassCount; ++p)
    if (!by_pass[p].empty()) pass_count = p + 1u;
  const uint32_t bands = static_cast<uint32_t>(options.band_edges.size());
  CalibrationContent c;
  c.header.pass_count = pass_count;
  c.header.level_count = kCalibratedLevels;
  c.header.band_count = bands;
  c.header.target_precision = options.target_precision;
  for (uint32_t b = 0; b < bands; ++b) c.header.band_min_density[b] = options.band_edges[b];
  c.header.scans_per_model = provenance.scans_per_model;
  c.header.models_left_out = provenance.models_left_out;
  c.header.clutter_scans = provenance.clutter_scans;
  c.header.scans_per_left_out = provenance.scans_per_left_out;
  c.header.seed = provenance.seed;
  c.header.clutter = provenance.clutter;
  for (uint32_t p = 0; p < pass_count; ++p) {
    const std::vector<CalibrationRun>& pass_runs = by_pass[p];
    if (pass_runs.empty() && p != static_cast<uint32_t>(AnswerPass::kFull)) {
      c.passes.push_back(blob::CalibrationPass{p, blob::kSourcePriors, 0u, 0.0f});
      c.cells.resize(c.cells.size() + static_cast<size_t>(kCalibratedLevels) * bands,
                     blob::CalibrationCell{});
      continue;
    }
    uint64_t known = 0, unknown = 0;
    for (const CalibrationRun& r : pass_runs) {
      known += r.kind == RunKind::kKnown ? 1u : 0u;
      unknown += r.kind == RunKind::kUnknown ? 1u : 0u;
    }
    const double unknown_weight = unknown > 0u && known > 0u ? static_cast<double>(known) / unknown : 1.0;
    const AnswerPass pass = static_cast<AnswerPass>(p);
    const bool agree = pass == AnswerPass::kAgree;  // its own target, in its record
    const float target = agree ? options.agree_precision : options.target_precision;
    const uint32_t min_runs =
        options.min_band_runs > 0u ? options.min_band_runs : default_min_band_runs(target);
    c.passes.push_back(blob::CalibrationPass{p, blob::kSourceFitted, static_cast<uint32_t>(pass_runs.size()),
                                             agree ? target : 0.0f});
    for (uint32_t l = 0; l < kCalibratedLevels; ++l) {
      LevelFitter fitter(pass_runs, options.band_edges, pass, static_cast<AnswerLevel>(l + 1u),
                         unknown_weight, target, min_runs);
      for (const Block& block : fitter.fit())
        for (uint32_t b = block.first; b <= block.last; ++b)
          c.cells.push_back(make_cell(fitter.samples(b, b), block.fit));
    }
  }
  *out = std::move(c);
  return true;
}

}  // namespace host
}  // namespace spinhash
