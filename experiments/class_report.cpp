// accuracy: the class level of the answers (Result::class_ranking): is the
// first class the scanned model's, and is `class_confident` right? Per
// condition and mode, with the median points on the vehicle (the sparse
// conditions are told by them).
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "accuracy_data.hpp"
#include "csv_table.hpp"
#include "plot_styles.hpp"

namespace spinhash::experiment {
namespace {

struct ClassTally {
  uint32_t queries = 0, right = 0, confident = 0, confident_right = 0, model_confident = 0;
  std::vector<uint32_t> object_points;
};

ClassTally tally(const AccuracyRun& run, int condition, uint32_t mode) {
  ClassTally t;
  for (const AccuracyRecord& r : run.records) {
    if (r.mode != mode || (condition >= 0 && r.condition != static_cast<uint32_t>(condition))) continue;
    const bool right = r.outcome.ranked > 0 && r.outcome.class_first == run.model_classes[r.model];
    ++t.queries;
    t.right += right ? 1u : 0u;
    t.confident += r.outcome.class_confident ? 1u : 0u;
    t.confident_right += r.outcome.class_confident && right ? 1u : 0u;
    t.model_confident += r.outcome.confident ? 1u : 0u;
    t.object_points.push_back(r.object_points);
  }
  return t;
}

uint32_t median(std::vector<uint32_t> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string pct(uint32_t a, uint32_t b) { return b ? num(100.0 * a / b, 3) + "%" : "-"; }

std::string row(const std::string& label, const std::string& mode, const ClassTally& t) {
  std::ostringstream s;
  s << "| " << label << " | " << mode << " | " << t.queries << " | " << median(t.object_points) << " | "
    << pct(t.right, t.queries) << " | " << t.confident << " | " << pct(t.confident_right, t.confident)
    << " | " << pct(t.confident_right, t.right) << " | " << t.model_confident << " |\n";
  return s.str();
}

}  // namespace

std::string class_section(const AccuracyRun& run) {
  std::ostringstream s;
  s << "\n## Class level (is the first class the scanned model's?)\n\nClass right first: the first class of "
    << "the class ranking is the scanned model's class; class confident: `class_confident`, with its "
    << "precision (right among the flagged) and recall (flagged among the right); model confident: "
    << "`confident` for comparison. Points: median points on the vehicle.\n\n"
    << "| condition | mode | queries | points | class right first | class confident | precision | recall | "
    << "model confident |\n|---|---|---|---|---|---|---|---|---|\n";
  s << rows_by_condition(run, [&run](const std::string& label, uint32_t m, int c) {
    return row(label, mode_title(run.modes[m]), tally(run, c, m));
  });
  return s.str();
}

}  // namespace spinhash::experiment
