// scaling: CSVs, plots (Figure 10, hypotheses, build cost) and summary.md.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "config/mode_name.hpp"
#include "csv_table.hpp"
#include "gnuplot.hpp"
#include "output_dir.hpp"
#include "plot_styles.hpp"
#include "scaling_data.hpp"
#include "stats.hpp"

namespace spinhash::experiment {
namespace {

// The paper's claims (section 10) and the project's targets for scaling.
constexpr uint32_t kReferenceModels = 56;     // the paper's database
constexpr double kMaxBranGrowth = 2.5;        // BRAN time at ~1000 models <= 2.5x that at 56
constexpr double kMinSpeedup = 20.0;          // BRAN >= 20x faster than SRAN at ~1000
constexpr double kMinHypothesisRatio = 10.0;  // with >= 10x fewer hypotheses
constexpr double kMaxBytesPerFeature = 160.0;
constexpr double kBytesPerMegabyte = 1e6;

struct Cell {  // one (size, mode)
  std::vector<double> ms, hyp;
  std::vector<uint32_t> ranks;
  uint32_t budget = 0;
  uint32_t confident = 0, confident_wrong = 0;  // `confident` answers, and those not ranked right first
  double top(uint32_t k) const {
    if (ranks.empty()) return 0.0;
    return static_cast<double>(
               std::count_if(ranks.begin(), ranks.end(), [k](uint32_t r) { return r >= 1 && r <= k; })) /
           static_cast<double>(ranks.size());
  }
};

Cell cell(const ScalingRun& run, uint32_t size, uint32_t mode, uint32_t max_query = ~0u) {
  Cell c;
  for (const ScalingRecord& r : run.records)
    if (r.size == size && r.mode == mode && r.query < max_query) {
      c.ms.push_back(r.outcome.ms);
      c.hyp.push_back(r.outcome.hypotheses);
      c.ranks.push_back(r.outcome.rank);
      c.budget += r.outcome.budget_exhausted ? 1u : 0u;
      c.confident += r.outcome.confident ? 1u : 0u;
      c.confident_wrong += r.outcome.confident && r.outcome.rank != 1u ? 1u : 0u;
    }
  return c;
}

int mode_index(const ScalingRun& run, Mode m) {
  for (size_t i = 0; i < run.modes.size(); ++i)
    if (run.modes[i] == m) return static_cast<int>(i);
  return -1;
}

uint32_t reference_size(const ScalingRun& run) {  // the size nearest the paper's 56
  uint32_t best = 0;
  for (uint32_t s = 1; s < run.builds.size(); ++s)
    if (std::abs(static_cast<double>(run.builds[s].models) - kReferenceModels) <
        std::abs(static_cast<double>(run.builds[best].models) - kReferenceModels))
      best = s;
  return best;
}

bool write_csvs(const ScalingRun& run, std::string* error) {
  CsvTable per_query({"models", "mode", "query", "model", "status", "rank", "ms", "hypotheses", "features",
                      "budget_exhausted", "confident", "group_size"});
  for (const ScalingRecord& r : run.records)
    per_query.add({std::to_string(run.builds[r.size].models), host::mode_name(run.modes[r.mode]),
                   std::to_string(r.query), std::to_string(r.model), status_name(r.outcome.status),
                   std::to_string(r.outcome.rank), num(r.outcome.ms), std::to_string(r.outcome.hypotheses),
                   std::to_string(r.outcome.features), r.outcome.budget_exhausted ? "1" : "0",
                   r.outcome.confident ? "1" : "0", std::to_string(r.outcome.group_size)});
  CsvTable longform({"models", "features", "mode", "queries", "median_ms", "mean_ms", "median_hypotheses",
                     "mean_hypotheses", "top1", "top5", "budget_exhausted"});
  std::vector<std::string> head{"models", "features"};
  for (Mode m : run.modes) {
    std::string n = host::mode_name(m);
    head.insert(head.end(), {n + "_median_ms", n + "_mean_ms", n + "_mean_hypotheses", n + "_top1"});
  }
  CsvTable wide(head);
  CsvTable build({"models", "features", "build_s", "serialize_s", "blob_bytes", "bytes_per_feature",
                  "largest_bucket", "mean_bucket"});
  for (uint32_t s = 0; s < run.builds.size(); ++s) {
    const BuildPoint& b = run.builds[s];
    std::vector<std::string> row{std::to_string(b.models), std::to_string(b.features)};
    for (uint32_t m = 0; m < run.modes.size(); ++m) {
      Cell c = cell(run, s, m);
      longform.add({std::to_string(b.models), std::to_string(b.features), host::mode_name(run.modes[m]),
                    std::to_string(c.ms.size()), num(median_of(c.ms)), num(mean_of(c.ms)),
                    num(median_of(c.hyp)), num(mean_of(c.hyp)), num(c.top(1)), num(c.top(5)),
                    std::to_string(c.budget)});
      row.insert(row.end(), {num(median_of(c.ms)), num(mean_of(c.ms)), num(mean_of(c.hyp)), num(c.top(1))});
    }
    wide.add(row);
    build.add({std::to_string(b.models), std::to_string(b.features), num(b.build_seconds),
               num(b.serialize_seconds), std::to_string(b.blob_bytes),
               num(static_cast<double>(b.blob_bytes) / b.features), std::to_string(b.max_bucket),
               num(b.mean_bucket)});
  }
  return per_query.write(run.out_dir + "/per_query.csv", error) &&
         longform.write(run.out_dir + "/scaling.csv", error) &&
         wide.write(run.out_dir + "/scaling_wide.csv", error) &&
         build.write(run.out_dir + "/build.csv", error);
}

// plot command over scaling_wide.csv: column `offset` of each mode's block of 4.
std::string mode_series(const ScalingRun& run, int offset, bool skip_sind) {
  std::ostringstream s;
  bool first = true;
  for (size_t m = 0; m < run.modes.size(); ++m) {
    if (skip_sind && run.modes[m] == Mode::kSind) continue;
    s << (first ? "" : ", ") << "'scaling_wide.csv' using 1:" << 3 + 4 * m + offset << " with linespoints ls "
      << mode_style(run.modes[m]) << " title '" << mode_title(run.modes[m]) << "'";
    first = false;
  }
  return s.str() + "\n";
}

bool write_plots(const ScalingRun& run, std::vector<std::string>* made, std::string* error) {
  const std::string x = "set xlabel 'models in the database'\n";
  std::ostringstream t;
  t << plot_style_lines() << x << "set key top left\nset multiplot layout 1,2 title 'Median time per query ("
    << run.queries << " queries from the first " << run.query_pool << " models)'\n"
    << "set title 'linear axes (paper Figure 10)'\nset ylabel 'ms per query'\nset yrange [0:*]\nplot "
    << mode_series(run, 0, false) << "set title 'log-log'\nset logscale xy\nset yrange [*:*]\nplot "
    << mode_series(run, 0, false) << "unset multiplot\n";
  std::ostringstream h;
  h << plot_style_lines() << x
    << "set key top left\nset logscale xy\nset ylabel 'hypotheses verified per query'\n"
    << "set title 'Mean hypotheses per query (SIND verifies none)'\nplot " << mode_series(run, 2, true);
  std::ostringstream a;
  a << plot_style_lines() << x << "set key bottom left\nset logscale x\nset yrange [0:1.02]\n"
    << "set ylabel 'P(correct model ranked first)'\nset title 'Top-1 accuracy of the same queries (SRAN: "
       "first "
    << run.sran_queries_large << " at >= " << run.sran_large_from << " models)'\nplot "
    << mode_series(run, 3, false);
  std::ostringstream b;
  b << plot_style_lines() << "set key top left\nset xlabel 'features in the database'\n"
    << "set xrange [0:*]\nset yrange [0:*]\n"
    << "set multiplot layout 1,2 title 'Database build (in memory, after the model scans)'\n"
    << "set title 'build time'\nset ylabel 's'\nf(x) = a*x + c\nfit f(x) 'build.csv' using 2:3 via a, c\n"
    << "plot 'build.csv' using 2:3 with linespoints ls 1 title 'features + grids + LSH', f(x) ls 9 "
       "title 'least-squares line'\n"
    << "set title 'blob size'\nset ylabel 'MB'\nplot 'build.csv' using 2:($5/" << kBytesPerMegabyte
    << ") with linespoints ls 2 title 'blob', x*" << kMaxBytesPerFeature / kBytesPerMegabyte
    << " ls 9 title '" << kMaxBytesPerFeature << " B/feature'\nunset multiplot\n";
  const std::pair<std::string, std::string> plots[] = {{"time_per_query", t.str()},
                                                       {"hypotheses_per_query", h.str()},
                                                       {"top1_per_size", a.str()},
                                                       {"build_cost", b.str()}};
  for (const auto& p : plots) {
    const bool wide = p.first == "time_per_query" || p.first == "build_cost";
    if (!render_plot(run.out_dir, p.first, "set fit quiet\nset fit logfile '/dev/null'\n" + p.second,
                     wide ? 1100 : 640, 480, error))
      return false;
    made->push_back(plot_file(p.first));
  }
  return true;
}

std::string verdict(bool ok) { return ok ? "met" : "**missed**"; }

std::string targets(const ScalingRun& run) {
  std::ostringstream s;
  const int b = mode_index(run, Mode::kBran), r = mode_index(run, Mode::kSran);
  const uint32_t ref = reference_size(run), big = static_cast<uint32_t>(run.builds.size() - 1);
  const uint32_t m_ref = run.builds[ref].models, m_big = run.builds[big].models;
  s << "\n## Targets (BRAN sub-linear and far cheaper than SRAN), " << m_big << " against " << m_ref
    << " models\n\n| target | measured | verdict |\n"
    << "|---|---|---|\n";
  if (b >= 0) {
    double g = median_of(cell(run, big, b).ms) / median_of(cell(run, ref, b).ms);
    s << "| BRAN time at " << m_big << " <= " << kMaxBranGrowth << "x that at " << m_ref << " | " << num(g, 3)
      << "x (median) | " << verdict(g <= kMaxBranGrowth) << " |\n";
  }
  if (r >= 0) {
    std::vector<double> lx, ly;
    for (uint32_t i = 0; i < run.builds.size(); ++i) {
      lx.push_back(std::log(static_cast<double>(run.builds[i].models)));
      ly.push_back(std::log(median_of(cell(run, i, r).ms)));
    }
    LineFit f = fit_line(lx, ly);
    s << "| SRAN about linear in the models | time ~ models^" << num(f.slope, 3) << " (log-log fit, R^2 "
      << num(f.r2, 3) << ") | " << verdict(f.slope > 0.8 && f.slope < 1.2) << " |\n";
  }
  if (b >= 0 && r >= 0) {
    Cell cr = cell(run, big, r);
    const uint32_t n = static_cast<uint32_t>(cr.ms.size());
    Cell cb = cell(run, big, b, n);  // the same queries
    double speed = mean_of(cr.ms) / mean_of(cb.ms), hyp = mean_of(cr.hyp) / std::max(mean_of(cb.hyp), 1e-9);
    s << "| BRAN >= " << kMinSpeedup << "x faster than SRAN at " << m_big << " | " << num(speed, 3)
      << "x (mean over the " << n << " queries both ran) | " << verdict(speed >= kMinSpeedup) << " |\n"
      << "| with >= " << kMinHypothesisRatio << "x fewer hypotheses | " << num(hyp, 3) << "x | "
      << verdict(hyp >= kMinHypothesisRatio) << " |\n"
      << "| (context) top-1 on those " << n << " queries | BRAN " << num(100.0 * cb.top(1), 3) << "%, SRAN "
      << num(100.0 * cr.top(1), 3) << "% | - |\n";
  }
  double worst = 0.0;
  for (const BuildPoint& p : run.builds)
    worst = std::max(worst, static_cast<double>(p.blob_bytes) / p.features);
  s << "| blob <= " << kMaxBytesPerFeature << " bytes per model feature | " << num(worst, 4)
    << " B/feature (worst size) | " << verdict(worst <= kMaxBytesPerFeature) << " |\n";
  std::vector<double> fx, fy;
  for (const BuildPoint& p : run.builds) fx.push_back(p.features), fy.push_back(p.build_seconds);
  LineFit bf = fit_line(fx, fy);
  const BuildPoint &lo = run.builds.front(), &hi = run.builds.back();
  double per_lo = 1e6 * lo.build_seconds / lo.features, per_hi = 1e6 * hi.build_seconds / hi.features;
  s << "| build time linear in features | R^2 " << num(bf.r2, 4) << "; " << num(per_lo, 3)
    << " us/feature at " << lo.models << " models, " << num(per_hi, 3) << " at " << hi.models << " | "
    << verdict(bf.r2 > 0.98 && per_hi < 2.0 * per_lo) << " |\n";
  return s.str();
}

std::string summary(const ScalingRun& run, const std::vector<std::string>& plots) {
  std::ostringstream s;
  s << "# Scaling (paper Figure 10)\n\nCommand: `" << run.command << "`\n\n- Queries: " << run.queries
    << ", drawn in turn from the first " << run.query_pool << " models (in every database), noise "
    << run.noise * 100.0 << " cm, ray spacing " << run.spacing * 100.0
    << " cm, 3 views, random pose; the same queries at every size. SRAN runs only the first "
    << run.sran_queries_large << " at sizes >= " << run.sran_large_from
    << " (it is linear in the models); its speed-up is compared on those same queries.\n"
    << "- Models: " << run.source << "\n- Recognizer (library defaults): " << run.recognizer
    << "\n- Largest database: " << run.database
    << "\n- Model scans (once, largest fleet): " << num(run.scan_seconds, 3)
    << " s\n- Wall times on a shared 2-core machine: noisy; instruction counts from "
       "scripts/instructions-per-query.sh are the stable measure.\n\n"
    << "## Time and hypotheses per query\n\n| models | features | mode | queries | median ms | mean ms | "
       "median hypotheses | mean hypotheses | budget cut | top-1 | top-5 | confident (wrong) "
       "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (uint32_t i = 0; i < run.builds.size(); ++i)
    for (uint32_t m = 0; m < run.modes.size(); ++m) {
      Cell c = cell(run, i, m);
      s << "| " << run.builds[i].models << " | " << run.builds[i].features << " | "
        << mode_title(run.modes[m]) << " | " << c.ms.size() << " | " << num(median_of(c.ms), 4) << " | "
        << num(mean_of(c.ms), 4) << " | " << num(median_of(c.hyp), 4) << " | " << num(mean_of(c.hyp), 4)
        << " | " << num(100.0 * c.budget / std::max<size_t>(c.ms.size(), 1), 3) << "% | "
        << num(100.0 * c.top(1), 3) << "% | " << num(100.0 * c.top(5), 3) << "% | " << c.confident << " ("
        << c.confident_wrong << ") |\n";
    }
  s << "\n## Build\n\n| models | features | build s | blob bytes | B/feature | largest LSH bucket |\n"
    << "|---|---|---|---|---|---|\n";
  for (const BuildPoint& b : run.builds)
    s << "| " << b.models << " | " << b.features << " | " << num(b.build_seconds, 4) << " | " << b.blob_bytes
      << " | " << num(static_cast<double>(b.blob_bytes) / b.features, 4) << " | " << b.max_bucket << " |\n";
  s << targets(run)
    << "\n## Files\n\n- `scaling.csv` (per size and mode), `scaling_wide.csv` (the same, one row "
    << "per size), `build.csv`, `per_query.csv`\n- Plots:";
  for (const std::string& p : plots) s << " `" << p << "`";
  s << "\n";
  return s.str();
}

}  // namespace

bool write_scaling_report(const ScalingRun& run, std::string* error) {
  if (run.builds.empty()) {
    *error = "no database size measured";
    return false;
  }
  std::vector<std::string> plots;
  if (!write_csvs(run, error)) return false;
  std::string plot_error;
  if (!write_plots(run, &plots, &plot_error)) plots.push_back("(plots failed: " + plot_error + ")");
  return write_text(run.out_dir + "/summary.md", summary(run, plots), error);
}

}  // namespace spinhash::experiment
