// accuracy: CSVs (per query, curves, timing), plots and summary.md.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "accuracy_data.hpp"
#include "config/mode_name.hpp"
#include "csv_table.hpp"
#include "gnuplot.hpp"
#include "output_dir.hpp"
#include "plot_styles.hpp"
#include "spinhash/vehicle_class.hpp"
#include "stats.hpp"

namespace spinhash::experiment {
namespace {

constexpr double kBranSranTolerance =
    0.02;                             // BRAN within 2 points of SRAN at every k (the paper: "the same level")
constexpr double kSindMargin = 0.10;  // "clearly below": 10 points under both at k = 1
const uint32_t kTableKs[] = {1, 2, 3, 5, 10, 20};
constexpr size_t kListedModels = 5;
constexpr int kPanelWidth = 420, kPanelHeight = 330, kMinPageWidth = 640;

std::vector<const AccuracyRecord*> select(const AccuracyRun& run, uint32_t condition, uint32_t mode) {
  std::vector<const AccuracyRecord*> out;
  for (const AccuracyRecord& r : run.records)
    if (r.condition == condition && r.mode == mode) out.push_back(&r);
  return out;
}

std::string curve_file(const QueryCondition& c) { return "curves/" + c.label() + ".csv"; }

std::string condition_title(const QueryCondition& c) {
  std::ostringstream s;
  s << "noise " << c.noise * 100.0 << " cm, occlusion " << c.occlusion * 100.0 << "%"
    << (c.ground == Ground::kScanned ? ", ground removed"
        : c.ground == Ground::kKept  ? ", ground kept (removal off)"
                                     : "");
  if (c.spacing != kPaperQuerySpacing) s << ", spacing " << c.spacing * 100.0 << " cm";
  if (c.slope_deg > 0.0) s << ", slope " << c.slope_deg << " deg";
  return s.str();
}

std::string pct(double p) { return num(100.0 * p, 3); }

struct ModeSummary {
  uint32_t queries = 0, not_ok = 0, budget = 0;
  double median_ms = 0, mean_ms = 0, median_hyp = 0, mean_hyp = 0, mean_points = 0;
  double rotation_error_deg = 0, translation_error_m = 0;  // medians over the right answers
};

ModeSummary summarise(const std::vector<const AccuracyRecord*>& rs) {
  ModeSummary s;
  std::vector<double> ms, hyp, pts, rot, trans;
  for (const AccuracyRecord* r : rs) {
    if (r->outcome.rank == 1 && std::isfinite(r->outcome.rotation_error_deg)) {
      rot.push_back(r->outcome.rotation_error_deg);
      trans.push_back(r->outcome.translation_error_m);
    }
    ++s.queries;
    s.not_ok += r->outcome.status != Status::kOk ? 1u : 0u;
    s.budget += r->outcome.budget_exhausted ? 1u : 0u;
    ms.push_back(r->outcome.ms);
    hyp.push_back(r->outcome.hypotheses);
    pts.push_back(r->points);
  }
  s.median_ms = median_of(ms);
  s.mean_ms = mean_of(ms);
  s.median_hyp = median_of(hyp);
  s.mean_hyp = mean_of(hyp);
  s.mean_points = mean_of(pts);
  s.rotation_error_deg = rot.empty() ? NAN : median_of(rot);
  s.translation_error_m = trans.empty() ? NAN : median_of(trans);
  return s;
}

bool write_csvs(const AccuracyRun& run, std::string* error) {
  CsvTable per_query({"mode",
                      "noise",
                      "occlusion",
                      "ground",
                      "spacing",
                      "model",
                      "name",
                      "query",
                      "points",
                      "status",
                      "rank",
                      "ms",
                      "hypotheses",
                      "features",
                      "ranked",
                      "best",
                      "confident",
                      "group_size",
                      "budget_exhausted",
                      "trials",
                      "score_first",
                      "score_second",
                      "inliers",
                      "rotation_error_deg",
                      "translation_error_m",
                      "object_points",
                      "class_true",
                      "class_first",
                      "class_confident",
                      "class_lead",
                      "surface_coverage",
                      "scan_density"});
  for (const AccuracyRecord& r : run.records) {
    const QueryCondition& c = run.conditions[r.condition];
    const Outcome& o = r.outcome;
    per_query.add({host::mode_name(run.modes[r.mode]),
                   num(c.noise),
                   num(c.occlusion),
                   ground_name(c.ground),
                   num(c.spacing),
                   std::to_string(r.model),
                   run.model_names[r.model],
                   std::to_string(r.query),
                   std::to_string(r.points),
                   status_name(o.status),
                   std::to_string(o.rank),
                   num(o.ms),
                   std::to_string(o.hypotheses),
                   std::to_string(o.features),
                   std::to_string(o.ranked),
                   o.ranked ? run.model_names[o.best_model] : "",
                   o.confident ? "1" : "0",
                   std::to_string(o.group_size),
                   o.budget_exhausted ? "1" : "0",
                   std::to_string(o.trials),
                   num(o.score_first),
                   num(o.score_second),
                   std::to_string(o.inliers),
                   num(o.rotation_error_deg),
                   num(o.translation_error_m),
                   std::to_string(r.object_points),
                   vehicle_class_name(run.model_classes[r.model]),
                   vehicle_class_name(o.class_first),
                   o.class_confident ? "1" : "0",
                   num(o.class_lead),
                   num(o.surface_coverage),
                   num(o.scan_density)});
  }
  CsvTable curves({"mode", "noise", "occlusion", "ground", "spacing", "k", "p_correct_within_k", "queries"});
  CsvTable timing({"mode", "noise", "occlusion", "ground", "spacing", "queries", "not_ok", "budget_exhausted",
                   "median_ms", "mean_ms", "median_hypotheses", "mean_hypotheses", "mean_points"});
  std::vector<std::string> wide_header{"condition"};
  for (Mode m : run.modes) wide_header.push_back(std::string(host::mode_name(m)) + "_median_ms");
  for (Mode m : run.modes) wide_header.push_back(std::string(host::mode_name(m)) + "_mean_hypotheses");
  CsvTable timing_wide(wide_header);
  for (uint32_t c = 0; c < run.conditions.size(); ++c) {
    const QueryCondition& cond = run.conditions[c];
    std::vector<std::string> head{"k"};
    for (Mode m : run.modes) head.push_back(mode_title(m));
    CsvTable one(head);
    std::vector<std::vector<double>> per_mode;
    std::vector<std::string> wide_ms{cond.label()}, wide_hyp;
    for (uint32_t m = 0; m < run.modes.size(); ++m) {
      per_mode.push_back(topk_curve(run, c, m));
      std::vector<const AccuracyRecord*> rs = select(run, c, m);
      ModeSummary s = summarise(rs);
      std::vector<std::string> cond_cols{host::mode_name(run.modes[m]), num(cond.noise), num(cond.occlusion),
                                         ground_name(cond.ground), num(cond.spacing)};
      for (uint32_t k = 1; k <= run.max_k; ++k) {
        std::vector<std::string> row = cond_cols;
        row.insert(row.end(), {std::to_string(k), num(per_mode.back()[k - 1]), std::to_string(rs.size())});
        curves.add(row);
      }
      std::vector<std::string> row = cond_cols;
      row.insert(row.end(),
                 {std::to_string(s.queries), std::to_string(s.not_ok), std::to_string(s.budget),
                  num(s.median_ms), num(s.mean_ms), num(s.median_hyp), num(s.mean_hyp), num(s.mean_points)});
      timing.add(row);
      wide_ms.push_back(num(s.median_ms));
      wide_hyp.push_back(num(std::max(s.mean_hyp, 0.5)));  // log axis: SIND's 0 drawn at 0.5
    }
    for (uint32_t k = 1; k <= run.max_k; ++k) {
      std::vector<std::string> row{std::to_string(k)};
      for (const auto& curve : per_mode) row.push_back(num(curve[k - 1]));
      one.add(row);
    }
    if (!one.write(run.out_dir + "/" + curve_file(cond), error)) return false;
    wide_ms.insert(wide_ms.end(), wide_hyp.begin(), wide_hyp.end());
    timing_wide.add(wide_ms);
  }
  return per_query.write(run.out_dir + "/per_query.csv", error) &&
         curves.write(run.out_dir + "/accuracy.csv", error) &&
         timing.write(run.out_dir + "/timing.csv", error) &&
         timing_wide.write(run.out_dir + "/timing_wide.csv", error);
}

std::string curve_plot_command(const AccuracyRun& run, const QueryCondition& c, bool key) {
  std::ostringstream s;
  s << (key ? "set key bottom right\n" : "unset key\n") << "set title '" << condition_title(c) << "'\nplot ";
  for (uint32_t m = 0; m < run.modes.size(); ++m)
    s << (m ? ", " : "") << "'" << curve_file(c) << "' using 1:" << m + 2 << " with linespoints ls "
      << mode_style(run.modes[m]) << " title '" << mode_title(run.modes[m]) << "'";
  s << "\n";
  return s.str();
}

std::string curve_axes(const AccuracyRun& run) {
  std::ostringstream s;
  s << plot_style_lines() << "set xrange [0.8:" << run.max_k + 0.2 << "]\nset yrange [0:1.02]\n"
    << "set xtics 1\nset xlabel 'k (models in the short list)'\nset ylabel 'P(correct model in top k)'\n";
  return s.str();
}

bool write_plots(const AccuracyRun& run, std::vector<std::string>* made, std::string* error) {
  // One figure per condition, then all of them on one page.
  for (const QueryCondition& c : run.conditions) {
    std::string name = "accuracy_" + c.label();
    if (!render_plot(run.out_dir, name, curve_axes(run) + curve_plot_command(run, c, true), 640, 480, error))
      return false;
    made->push_back(plot_file(name));
  }
  // All conditions of one ground state on one page.
  std::vector<double> occ;
  for (const QueryCondition& c : run.conditions)
    if (std::find(occ.begin(), occ.end(), c.occlusion) == occ.end()) occ.push_back(c.occlusion);
  const size_t cols = occ.size();
  std::vector<std::string> overviews;
  for (Ground g : {Ground::kNone, Ground::kScanned, Ground::kKept}) {
    std::vector<const QueryCondition*> page;
    for (const QueryCondition& c : run.conditions)
      if (c.ground == g) page.push_back(&c);
    if (page.empty()) continue;
    const size_t rows = (page.size() + cols - 1) / cols;
    const std::string name = std::string("accuracy_overview") + (g == Ground::kNone ? "" : "_ground") +
                             (g == Ground::kKept ? "_kept" : "");
    std::ostringstream body;
    body << curve_axes(run) << "set multiplot layout " << rows << "," << cols << " title '"
         << run.model_names.size() << " models, " << run.queries_per_model * run.query_models
         << " queries per condition"
         << (g == Ground::kScanned ? ", ground scanned (removed by the recognizer)" : "")
         << (g == Ground::kKept ? ", ground scanned and kept (removal off)" : "") << "'\n";
    for (size_t i = 0; i < page.size(); ++i) body << curve_plot_command(run, *page[i], i == 0);
    body << "unset multiplot\n";
    if (!render_plot(run.out_dir, name, body.str(),
                     std::max(kMinPageWidth, static_cast<int>(cols) * kPanelWidth),
                     static_cast<int>(rows) * kPanelHeight + 40, error))
      return false;
    overviews.push_back(plot_file(name));
  }
  made->insert(made->begin(), overviews.begin(), overviews.end());
  // Median time and mean hypotheses per condition, clustered by mode.
  std::ostringstream t;
  const size_t n = run.modes.size();
  t << plot_style_lines() << "set style data histograms\nset style histogram clustered gap 1\n"
    << "set style fill solid 0.85 border -1\nset logscale y\nset xtics rotate by -35 font ',9'\n"
    << "set key top left\nset multiplot layout 2,1\n"
    << "set title 'median time per query'\nset ylabel 'ms'\nplot ";
  for (size_t m = 0; m < n; ++m)
    t << (m ? ", " : "") << "'timing_wide.csv' using " << m + 2 << (m ? "" : ":xtic(1)") << " ls "
      << mode_style(run.modes[m]) << " title '" << mode_title(run.modes[m]) << "'";
  t << "\nset title 'mean hypotheses per query (SIND verifies none: drawn at 0.5)'\nset ylabel "
       "'hypotheses'\nplot ";
  for (size_t m = 0; m < n; ++m)
    t << (m ? ", " : "") << "'timing_wide.csv' using " << n + m + 2 << (m ? "" : ":xtic(1)") << " ls "
      << mode_style(run.modes[m]) << " title '" << mode_title(run.modes[m]) << "'";
  t << "\nunset multiplot\n";
  if (!render_plot(run.out_dir, "timing", t.str(), 900, 800, error)) return false;
  made->push_back(plot_file("timing"));
  return true;
}

int mode_index(const AccuracyRun& run, Mode m) {
  for (size_t i = 0; i < run.modes.size(); ++i)
    if (run.modes[i] == m) return static_cast<int>(i);
  return -1;
}

// The accuracy targets (BRAN within 2 points of SRAN, SIND below both), per condition.
std::string target_section(const AccuracyRun& run) {
  std::ostringstream s;
  const int b = mode_index(run, Mode::kBran), r = mode_index(run, Mode::kSran),
            d = mode_index(run, Mode::kSind);
  s << "\n## Targets (BRAN within 2 points of SRAN; SIND below both)\n\n";
  if (b < 0 || r < 0) {
    s << "BRAN and SRAN both needed to check the targets.\n";
    return s.str();
  }
  s << "| condition | worst SRAN - BRAN (points, at k) | BRAN within 2 points? |";
  if (d >= 0) s << " SIND top-1 vs min(BRAN, SRAN) top-1 | SIND clearly below (>= 10 points)? |";
  s << "\n|---|---|---|" << (d >= 0 ? "---|---|" : "") << "\n";
  for (uint32_t c = 0; c < run.conditions.size(); ++c) {
    std::vector<double> cb = topk_curve(run, c, b), cr = topk_curve(run, c, r);
    double worst = -1.0;
    uint32_t at = 1;
    for (uint32_t k = 0; k < run.max_k; ++k)
      if (cr[k] - cb[k] > worst) worst = cr[k] - cb[k], at = k + 1;
    s << "| " << condition_title(run.conditions[c]) << " | " << num(100.0 * worst, 3) << " (k = " << at
      << ") | " << (worst <= kBranSranTolerance + 1e-9 ? "met" : "**missed**") << " |";
    if (d >= 0) {
      double sind1 = topk_curve(run, c, d)[0], both1 = std::min(cb[0], cr[0]);
      s << " " << pct(sind1) << "% vs " << pct(both1) << "% | "
        << (both1 - sind1 >= kSindMargin ? "met" : "**missed**") << " |";
    }
    s << "\n";
  }
  return s.str();
}

// The condition with `ground` and the same noise and occlusion as c, or -1.
int matching(const AccuracyRun& run, const QueryCondition& c, Ground ground) {
  for (size_t i = 0; i < run.conditions.size(); ++i) {
    const QueryCondition& o = run.conditions[i];
    if (o.ground == ground && o.noise == c.noise && o.occlusion == c.occlusion && o.spacing == c.spacing &&
        o.slope_deg == 0.0)
      return static_cast<int>(i);
  }
  return -1;
}

std::string ground_section(const AccuracyRun& run) {
  std::ostringstream s;
  bool scanned = false, kept = false;
  for (const QueryCondition& c : run.conditions) {
    scanned = scanned || c.ground == Ground::kScanned;
    kept = kept || c.ground == Ground::kKept;
  }
  if (!scanned && !kept) return "";
  s << "\n## Ground (every airborne scan has it)\n\nTop-1 without ground";
  if (scanned)
    s << " -> with a ground square reaching " << run.ground_margin
      << " m beyond the vehicle scanned too (the recognizer's default level-ground removal, ground_clearance "
      << GroundParams{}.ground_clearance << " m)";
  if (kept) s << " -> the same scans with the ground removal off (what a pipeline without it sees)";
  s << ":\n\n| noise, occlusion |";
  for (Mode m : run.modes) s << " " << mode_title(m) << " |";
  s << "\n|---|";
  for (size_t m = 0; m < run.modes.size(); ++m) s << "---|";
  s << "\n";
  for (uint32_t c = 0; c < run.conditions.size(); ++c) {
    const QueryCondition& off = run.conditions[c];
    if (off.ground != Ground::kNone) continue;
    const int on = matching(run, off, Ground::kScanned), kept_c = matching(run, off, Ground::kKept);
    s << "| " << off.noise * 100.0 << " cm, " << off.occlusion * 100.0 << "%";
    if (off.spacing != kPaperQuerySpacing) s << ", spacing " << off.spacing * 100.0 << " cm";
    s << " |";
    for (uint32_t m = 0; m < run.modes.size(); ++m) {
      s << " " << pct(topk_curve(run, c, m)[0]) << "%";
      if (on >= 0) s << " -> " << pct(topk_curve(run, static_cast<uint32_t>(on), m)[0]) << "%";
      if (kept_c >= 0) s << " -> " << pct(topk_curve(run, static_cast<uint32_t>(kept_c), m)[0]) << "%";
      s << " |";
    }
    s << "\n";
  }
  if (!kept) return s.str();
  s << "\nModels most often ranked first with the ground kept (all modes):";
  std::vector<uint32_t> firsts(run.model_names.size(), 0);
  for (const AccuracyRecord& r : run.records)
    if (run.conditions[r.condition].ground == Ground::kKept && r.outcome.ranked > 0)
      ++firsts[r.outcome.best_model];
  std::vector<uint32_t> order(firsts.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return firsts[a] > firsts[b]; });
  for (size_t i = 0; i < std::min<size_t>(kListedModels, order.size()) && firsts[order[i]] > 0; ++i)
    s << (i ? ", " : " ") << run.model_names[order[i]] << " (" << firsts[order[i]] << ")";
  s << ".\n";
  return s.str();
}

std::string summary(const AccuracyRun& run, const std::vector<std::string>& plots) {
  std::ostringstream s;
  s << "# Accuracy (paper Figure 9)\n\nCommand: `" << run.command << "`\n\n"
    << "- Models: " << run.source << "\n- Database: " << run.database
    << "\n- Recognizer (library defaults): " << run.recognizer << "\n- Queries: " << run.queries_per_model
    << " per model x " << run.query_models << " models = " << run.queries_per_model * run.query_models
    << " per condition; 3 views 45 degrees apart at 45 degrees elevation from a random side, random pose"
    << " (yaw, +-50 m), Gaussian noise along the rays, optional slab occluder; the same sides and poses under"
    << " every condition.\n\n## P(correct model within the top k), time and hypotheses per query\n\nBudget "
       "cut: queries the"
    << " work budget stopped; pose error: medians over the right answers of the rotation's angle and the"
    << " translation's distance from the scan's true pose.\n\n"
    << "| condition | mode |";
  std::vector<uint32_t> ks;
  for (uint32_t k : kTableKs)
    if (k <= run.max_k) ks.push_back(k);
  for (uint32_t k : ks) s << " top-" << k << " |";
  s << " median ms | mean ms | median hypotheses | budget cut | pose error (deg / m) | failed |\n|---|---|";
  for (size_t i = 0; i < ks.size(); ++i) s << "---|";
  s << "---|---|---|---|---|---|\n";
  for (uint32_t c = 0; c < run.conditions.size(); ++c)
    for (uint32_t m = 0; m < run.modes.size(); ++m) {
      std::vector<double> curve = topk_curve(run, c, m);
      ModeSummary ms = summarise(select(run, c, m));
      s << "| " << condition_title(run.conditions[c]) << " | " << mode_title(run.modes[m]) << " |";
      for (uint32_t k : ks) s << " " << pct(curve[k - 1]) << "% |";
      s << " " << num(ms.median_ms, 4) << " | " << num(ms.mean_ms, 4) << " | " << num(ms.median_hyp, 4)
        << " | " << pct(static_cast<double>(ms.budget) / std::max(1u, ms.queries)) << "% | "
        << num(ms.rotation_error_deg, 3) << " / " << num(ms.translation_error_m, 3) << " | " << ms.not_ok
        << " |\n";
    }
  s << target_section(run) << ground_section(run) << confidence_section(run) << class_section(run)
    << "\n## Files\n\n"
    << "- `accuracy.csv`: P(correct within top k) per mode, condition and k; `curves/*.csv`: the same, one "
       "file "
       "per condition\n- `timing.csv`: time and hypotheses per mode and condition\n"
    << "- `per_query.csv`: every recognition (rank of the true model, 0 = not ranked)\n"
    << "- `calibration.csv`: confident answers against right ones, per mode and condition\n- Plots:";
  for (const std::string& p : plots) s << " `" << p << "`";
  s << "\n";
  return s.str();
}

}  // namespace

std::vector<double> topk_curve(const AccuracyRun& run, uint32_t condition, uint32_t mode) {
  std::vector<const AccuracyRecord*> rs = select(run, condition, mode);
  std::vector<double> curve(run.max_k, 0.0);
  if (rs.empty()) return curve;
  for (uint32_t k = 1; k <= run.max_k; ++k) {
    size_t hits = std::count_if(rs.begin(), rs.end(), [k](const AccuracyRecord* r) {
      return r->outcome.rank >= 1 && r->outcome.rank <= k;
    });
    curve[k - 1] = static_cast<double>(hits) / static_cast<double>(rs.size());
  }
  return curve;
}

bool write_accuracy_report(const AccuracyRun& run, std::string* error) {
  std::vector<std::string> plots;
  if (!make_output_dir(run.out_dir + "/curves", error) || !write_csvs(run, error) ||
      !write_calibration_csv(run, error))
    return false;
  std::string plot_error;
  if (!write_plots(run, &plots, &plot_error)) plots.push_back("(plots failed: " + plot_error + ")");
  return write_text(run.out_dir + "/summary.md", summary(run, plots), error);
}

}  // namespace spinhash::experiment
