#include "cli/calibration_report.hpp"

#include <cstdio>
#include <vector>

#include "calib/calibration_scans.hpp"
#include "cli/json_line.hpp"
#include "cli/report_keys.hpp"

namespace spinhash::cli {
namespace {

std::string band_label(const Calibration& c, uint32_t b) {
  char text[48];
  if (b + 1u < c.band_count())
    std::snprintf(text, sizeof text, "%g-%g", static_cast<double>(c.band_min_density(b)),
                  static_cast<double>(c.band_min_density(b + 1u)));
  else
    std::snprintf(text, sizeof text, "%g+", static_cast<double>(c.band_min_density(b)));
  return text;
}

std::string num(float v) { return json_number(static_cast<double>(v), 7); }
std::string num(uint64_t v) { return std::to_string(v); }
std::string num(uint32_t v) { return std::to_string(v); }

std::string cell_json(const blob::CalibrationCell& cell) {
  namespace k = info_keys;
  return json_object(
      {json_member(k::kState, json_string(cell_state_word(cell.state))),
       json_member(k::kThreshold, num(cell.threshold)), json_member(k::kPrecision, num(cell.precision)),
       json_member(k::kRecall, num(cell.recall)), json_member(k::kPositives, num(cell.positives)),
       json_member(k::kNegatives, num(cell.negatives)), json_member(k::kFlagged, num(cell.flagged))});
}

std::string pass_json(const Calibration& c, uint32_t p) {
  namespace k = info_keys;
  const blob::CalibrationPass& rec = c.pass_record(p);
  const AnswerPass pass = static_cast<AnswerPass>(rec.pass);
  std::vector<std::string> levels;
  for (uint32_t l = 1; l <= kCalibratedLevels; ++l) {
    std::vector<std::string> cells;
    for (uint32_t b = 0; b < c.band_count(); ++b)
      cells.push_back(cell_json(*c.cell(pass, static_cast<AnswerLevel>(l), b)));
    levels.push_back(json_object({json_member(k::kLevel, json_string(answer_level_name(l))),
                                  json_member(k::kCells, json_array(cells))}));
  }
  const bool fitted = rec.source == blob::kSourceFitted;
  return json_object({json_member(k::kPass, json_string(answer_pass_name(rec.pass))),
                      json_member(k::kSource, json_string(fitted ? "fitted" : "priors")),
                      json_member(k::kTargetPrecision, fitted ? num(c.target_precision(pass)) : "null"),
                      json_member(k::kRuns, num(rec.runs)), json_member(k::kLevels, json_array(levels))});
}

}  // namespace

const char* cell_state_word(uint32_t state) {
  switch (state) {
    case blob::kCellPriors: return "priors";
    case blob::kCellFitted: return "fitted";
    case blob::kCellTooFew: return "too_few_runs";
    case blob::kCellUnreachable: return "unreachable";
    default: return "unknown";
  }
}

void print_calibration(const Calibration& c) {
  if (!c.present()) return;
  const blob::CalibrationHeader& h = c.header();
  bool any_fitted = false;
  for (uint32_t p = 0; p < c.pass_count(); ++p)
    any_fitted = any_fitted || c.pass_record(p).source == blob::kSourceFitted;
  if (!any_fitted) {
    std::printf(
        "calibration   none (built with --no-calibration): the recognizer's priors decide every flag\n");
    return;
  }
  std::printf(
      "calibration   target precision %g: %u scans per model, %u models left out (%u scans each), %u clutter "
      "scans (%s), seed %llu\n",
      static_cast<double>(h.target_precision), h.scans_per_model, h.models_left_out, h.scans_per_left_out,
      h.clutter_scans, calib::calibration_clutter_kinds(h.clutter), static_cast<unsigned long long>(h.seed));
  std::printf("  %-6s %-8s %-12s %10s %9s %7s %6s %6s %7s\n", "pass", "level", "points/m2", "threshold",
              "precision", "recall", "right", "wrong", "flagged");
  for (uint32_t p = 0; p < c.pass_count(); ++p) {
    const blob::CalibrationPass& rec = c.pass_record(p);
    const AnswerPass pass = static_cast<AnswerPass>(rec.pass);
    if (rec.source != blob::kSourceFitted) {
      std::printf("  %-6s priors: the recognizer's settings decide\n", answer_pass_name(rec.pass));
      continue;
    }
    if (rec.target_precision > 0.0f)
      std::printf("  %-6s fitted to precision %g\n", answer_pass_name(rec.pass),
                  static_cast<double>(rec.target_precision));
    for (uint32_t l = 1; l <= kCalibratedLevels; ++l)
      for (uint32_t b = 0; b < c.band_count(); ++b) {
        const blob::CalibrationCell& cell = *c.cell(pass, static_cast<AnswerLevel>(l), b);
        const std::string band = band_label(c, b);
        if (cell.state == blob::kCellFitted)
          std::printf("  %-6s %-8s %-12s %10.4g %9.4f %7.4f %6u %6u %7u\n", answer_pass_name(rec.pass),
                      answer_level_name(l), band.c_str(), static_cast<double>(cell.threshold),
                      static_cast<double>(cell.precision), static_cast<double>(cell.recall), cell.positives,
                      cell.negatives, cell.flagged);
        else
          std::printf("  %-6s %-8s %-12s %-27s %6u %6u %7s\n", answer_pass_name(rec.pass),
                      answer_level_name(l), band.c_str(),
                      cell.state == blob::kCellTooFew ? "never: too few runs" : "never: target unreachable",
                      cell.positives, cell.negatives, "0");
      }
  }
}

std::string calibration_json(const Calibration& c) {
  namespace k = info_keys;
  const blob::CalibrationHeader& h = c.header();
  std::vector<std::string> bands, passes;
  for (uint32_t b = 0; b < c.band_count(); ++b) bands.push_back(num(c.band_min_density(b)));
  for (uint32_t p = 0; p < c.pass_count(); ++p) passes.push_back(pass_json(c, p));
  return json_object({json_member(k::kTargetPrecision, num(h.target_precision)),
                      json_member(k::kScansPerModel, num(h.scans_per_model)),
                      json_member(k::kModelsLeftOut, num(h.models_left_out)),
                      json_member(k::kClutterScans, num(h.clutter_scans)),
                      json_member(k::kClutter, json_string(calib::calibration_clutter_word(h.clutter))),
                      json_member(k::kScansPerLeftOut, num(h.scans_per_left_out)),
                      json_member(k::kSeed, num(h.seed)), json_member(k::kBands, json_array(bands)),
                      json_member(k::kPasses, json_array(passes))});
}

}  // namespace spinhash::cli
