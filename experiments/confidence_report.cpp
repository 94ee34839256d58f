// accuracy: is `confident` a statement about correctness? Confident answers
// against right ones (right = the true model ranked first), per condition
// and mode and pooled per mode, with the targets of the API's contract; and
// whether the look-alike group of an answer that is not confident holds the
// true model.
#include <sstream>
#include <string>

#include "accuracy_data.hpp"
#include "config/mode_name.hpp"
#include "csv_table.hpp"
#include "plot_styles.hpp"

namespace spinhash::experiment {
namespace {

constexpr double kMinConfidentPrecision = 0.99;  // confident answers that are right
constexpr double kMinConfidentRecall = 0.90;     // right answers flagged confident

struct Tally {
  uint32_t queries = 0, right = 0, confident = 0, confident_right = 0;
  uint32_t wrong_lookalike = 0;  // wrong, and the answer is a look-alike copy of the truth (or the reverse)
  uint32_t unsure = 0, unsure_in_group = 0;  // answers not confident; those whose group holds the truth
  uint64_t unsure_group_sizes = 0;

  double group_recall() const { return unsure ? static_cast<double>(unsure_in_group) / unsure : 1.0; }
  double mean_group() const { return unsure ? static_cast<double>(unsure_group_sizes) / unsure : 0.0; }

  double precision() const { return confident ? static_cast<double>(confident_right) / confident : 1.0; }
  double recall() const { return right ? static_cast<double>(confident_right) / right : 1.0; }
};

// "van-03~sx+1" and "van-03" share the base "van-03".
std::string base_name(const std::string& name) { return name.substr(0, name.find('~')); }

void count(const AccuracyRun& run, const AccuracyRecord& r, Tally* t) {
  const Outcome& o = r.outcome;
  const bool right = o.rank == 1;
  ++t->queries;
  t->right += right ? 1u : 0u;
  t->confident += o.confident ? 1u : 0u;
  t->confident_right += o.confident && right ? 1u : 0u;
  if (!o.confident && o.ranked > 0) {
    ++t->unsure;
    t->unsure_in_group += o.rank >= 1 && o.rank <= o.group_size ? 1u : 0u;
    t->unsure_group_sizes += o.group_size;
  }
  if (!right && o.ranked > 0 &&
      base_name(run.model_names[o.best_model]) == base_name(run.model_names[r.model]))
    ++t->wrong_lookalike;
}

Tally tally(const AccuracyRun& run, int condition, uint32_t mode) {
  Tally t;
  for (const AccuracyRecord& r : run.records)
    if (r.mode == mode && (condition < 0 || r.condition == static_cast<uint32_t>(condition)))
      count(run, r, &t);
  return t;
}

std::string pct(double p) { return num(100.0 * p, 3) + "%"; }

std::string row(const std::string& label, const std::string& mode, const Tally& t) {
  std::ostringstream s;
  s << "| " << label << " | " << mode << " | " << t.queries << " | "
    << pct(t.queries ? double(t.right) / t.queries : 0) << " | " << t.confident << " | " << pct(t.precision())
    << (t.precision() >= kMinConfidentPrecision ? "" : " (below)") << " | " << pct(t.recall())
    << (t.recall() >= kMinConfidentRecall ? "" : " (below)") << " | " << t.confident - t.confident_right
    << " | " << t.wrong_lookalike << " | " << pct(t.group_recall()) << " | " << num(t.mean_group(), 3)
    << " |\n";
  return s.str();
}

}  // namespace

std::string confidence_section(const AccuracyRun& run) {
  std::ostringstream s;
  s << "\n## Confidence (is `confident` right?)\n\nPrecision: confident answers whose first model is right "
    << "(target >= " << pct(kMinConfidentPrecision)
    << "); recall: right answers flagged confident (target >= " << pct(kMinConfidentRecall)
    << "). Look-alike errors: wrong answers that name a look-alike copy of the "
    << "scanned model. In group: answers not confident whose look-alike group (the leading models "
    << "within min_margin of the first) holds the scanned model, and the mean size of that group."
    << "\n\n| condition | mode | queries | right first | confident | precision | recall | "
    << "confident and wrong | look-alike errors | in group | mean group |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  s << rows_by_condition(run, [&run](const std::string& label, uint32_t m, int c) {
    return row(label, mode_title(run.modes[m]), tally(run, c, m));
  });
  return s.str();
}

bool write_calibration_csv(const AccuracyRun& run, std::string* error) {
  CsvTable t({"mode", "condition", "queries", "right_first", "confident", "confident_right", "precision",
              "recall", "lookalike_errors", "unsure", "unsure_in_group", "mean_group"});
  for (int c = -1; c < static_cast<int>(run.conditions.size()); ++c)
    for (uint32_t m = 0; m < run.modes.size(); ++m) {
      const Tally x = tally(run, c, m);
      t.add({host::mode_name(run.modes[m]), c < 0 ? "all" : run.conditions[static_cast<size_t>(c)].label(),
             std::to_string(x.queries), std::to_string(x.right), std::to_string(x.confident),
             std::to_string(x.confident_right), num(x.precision()), num(x.recall()),
             std::to_string(x.wrong_lookalike), std::to_string(x.unsure), std::to_string(x.unsure_in_group),
             num(x.mean_group())});
    }
  return t.write(run.out_dir + "/calibration.csv", error);
}

}  // namespace spinhash::experiment
