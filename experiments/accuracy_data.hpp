// What `experiment accuracy` measured: one record per (condition, query, mode).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "query_runner.hpp"
#include "query_set.hpp"
#include "spinhash/config.hpp"

namespace spinhash::experiment {

struct AccuracyRecord {
  uint32_t condition = 0;  // index into AccuracyRun::conditions
  uint32_t mode = 0;       // index into AccuracyRun::modes
  uint32_t model = 0;
  uint32_t query = 0;
  uint32_t points = 0;         // query cloud size (object and ground)
  uint32_t object_points = 0;  // of them on the vehicle
  Outcome outcome;
};

struct AccuracyRun {
  std::string out_dir;
  std::string command;   // as typed
  std::string source;    // "procedural fleet" or the mesh inputs
  std::string database;  // config_text descriptions
  std::string recognizer;
  std::vector<std::string> model_names;  // every database model (originals first)
  std::vector<uint32_t> model_classes;   // their vehicle classes (VehicleClass ids)
  uint32_t query_models = 0;             // the originals, which the queries scan
  std::vector<QueryCondition> conditions;
  std::vector<Mode> modes;
  uint32_t queries_per_model = 0;
  uint32_t max_k = 0;
  double ground_margin = 0.0;
  std::vector<AccuracyRecord> records;
};

// P(true model within the top k) for k = 1..max_k, of one condition and mode.
std::vector<double> topk_curve(const AccuracyRun& run, uint32_t condition, uint32_t mode);

// A report's table body: `row(label, mode, condition)` for each mode pooled
// over all conditions (condition -1), then for each condition and mode.
template <class Row>
std::string rows_by_condition(const AccuracyRun& run, Row&& row) {
  std::string out;
  for (uint32_t m = 0; m < run.modes.size(); ++m) out += row("**all conditions**", m, -1);
  for (uint32_t c = 0; c < run.conditions.size(); ++c)
    for (uint32_t m = 0; m < run.modes.size(); ++m)
      out += row(run.conditions[c].label(), m, static_cast<int>(c));
  return out;
}

// Whether `confident` means right: per condition and mode, and pooled per
// mode. calibration.csv and a summary section.
std::string confidence_section(const AccuracyRun& run);
bool write_calibration_csv(const AccuracyRun& run, std::string* error);

// The class level: the first class against the scanned model's, and
// whether class_confident is right; per condition and mode. A summary section.
std::string class_section(const AccuracyRun& run);

// CSVs, plots and summary.md into run.out_dir; false with *error on a write failure.
bool write_accuracy_report(const AccuracyRun& run, std::string* error);

}  // namespace spinhash::experiment
