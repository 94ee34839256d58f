// lsh: CSVs, plots (collision probability, recall) and summary.md with a
// recommendation for K and L drawn from the measurements.
#include <algorithm>
#include <sstream>

#include "csv_table.hpp"
#include "gnuplot.hpp"
#include "lsh_data.hpp"
#include "output_dir.hpp"
#include "plot_styles.hpp"
#include "spinhash/internal/lsh_probability.hpp"
#include "spinhash/lsh.hpp"

namespace spinhash::experiment {
namespace {

constexpr uint64_t kMinPairsPerBin = 50;  // fewer: the measured share is too noisy to plot
constexpr double kRecallSlack = 0.02;     // "as good as the best": within 2 points of its match recall
constexpr int kExtraStyleBase = 1;        // configs use line styles 1..6

std::string config_name(const LshConfigResult& c) {
  return "K" + std::to_string(c.k) + "_L" + std::to_string(c.l);
}

std::string config_title(const LshConfigResult& c) {
  return "K=" + std::to_string(c.k) + " L=" + std::to_string(c.l) + (c.is_default ? " (default)" : "");
}

bool write_csvs(const LshRun& run, std::string* error) {
  CsvTable all({"k", "l", "d_lo", "d_hi", "d_mid", "pairs", "collisions", "measured", "eq2"});
  for (const LshConfigResult& c : run.configs) {
    CsvTable one({"d_mid", "measured", "eq2", "pairs"});
    for (size_t b = 0; b < c.pairs.size(); ++b) {
      const double lo = b * run.bin_width, hi = lo + run.bin_width, mid = 0.5 * (lo + hi);
      const double measured = c.pairs[b] ? static_cast<double>(c.collisions[b]) / c.pairs[b] : 0.0;
      const double eq2 = lsh_collision_probability(mid, run.d_c, c.k, c.l);
      all.add({std::to_string(c.k), std::to_string(c.l), num(lo), num(hi), num(mid),
               std::to_string(c.pairs[b]), std::to_string(c.collisions[b]), num(measured), num(eq2)});
      if (c.pairs[b] >= kMinPairsPerBin)
        one.add({num(mid), num(measured), num(eq2), std::to_string(c.pairs[b])});
    }
    if (!one.write(run.out_dir + "/collisions/" + config_name(c) + ".csv", error)) return false;
  }
  CsvTable recall({"k", "l", "default", "buckets", "largest_bucket", "mean_bucket", "probes",
                   "probes_with_match", "nn_recall", "topw_recall", "match_recall", "exhaustive_match_recall",
                   "true_model_share", "mean_candidates", "mean_entries_scanned", "truncated_share",
                   "us_per_lookup"});
  for (const LshConfigResult& c : run.configs)
    recall.add({std::to_string(c.k), std::to_string(c.l), c.is_default ? "1" : "0", std::to_string(c.buckets),
                std::to_string(c.max_bucket), num(c.mean_bucket), std::to_string(c.features),
                std::to_string(c.features_with_match), num(c.nn_recall), num(c.topw_recall),
                num(c.match_recall), num(run.exhaustive_match_recall), num(c.true_model_share),
                num(c.mean_candidates), num(c.mean_entries_scanned), num(c.truncated_share),
                num(c.us_per_lookup)});
  return all.write(run.out_dir + "/collision.csv", error) && recall.write(run.out_dir + "/recall.csv", error);
}

std::vector<uint32_t> distinct_l(const LshRun& run) {
  std::vector<uint32_t> ls;
  for (const LshConfigResult& c : run.configs)
    if (std::find(ls.begin(), ls.end(), c.l) == ls.end()) ls.push_back(c.l);
  return ls;
}

bool write_plots(const LshRun& run, std::vector<std::string>* made, std::string* error) {
  std::ostringstream c;
  c << plot_style_lines() << "dc = " << run.d_c << "\nP(x, K, L) = x >= dc ? 0 : 1 - (1 - (1 - x/dc)**K)**L\n"
    << "set samples 400\nset xrange [0:" << run.bin_width * run.bins << "]\n"
    << "set xlabel 'L1 distance of the clamped spin images (quantised units)'\n"
    << "set ylabel 'P(same key in >= 1 table)'\n"
    << "set arrow 1 from " << run.median_nn_distance << ", graph 0 to " << run.median_nn_distance
    << ", graph 1 nohead ls 9\nset arrow 2 from " << run.median_match_distance << ", graph 0 to "
    << run.median_match_distance << ", graph 1 nohead ls 9 dt 3\n"
    << "set label 1 'median NN' at " << run.median_nn_distance << ", graph 0.10 offset 0.5,0 font ',9'\n"
    << "set label 2 'median correct match' at " << run.median_match_distance
    << ", graph 0.04 offset 0.5,0 font ',9'\n"
    << "set multiplot layout 1,2 title 'LSH collisions: measured (points) against eq. 2 (lines), d_c = "
    << num(run.d_c, 5) << "'\n"
    << "set key top right font ',9'\nset title 'linear'\nset yrange [0:1.02]\nplot ";
  std::ostringstream series;
  for (size_t i = 0; i < run.configs.size(); ++i) {
    const LshConfigResult& r = run.configs[i];
    const int ls = kExtraStyleBase + static_cast<int>(i % 6);
    series << (i ? ", " : "") << "'collisions/" << config_name(r) << ".csv' using 1:2 with points ls " << ls
           << " title '" << config_title(r) << "', P(x, " << r.k << ", " << r.l << ") with lines ls " << ls
           << " notitle";
  }
  c << series.str() << "\nset title 'log scale'\nset logscale y\nset yrange [1e-6:1.5]\nplot " << series.str()
    << "\nunset multiplot\n";
  if (!render_plot(run.out_dir, "collision", c.str(), 1200, 520, error)) return false;
  made->push_back(plot_file("collision"));
  // Recall and cost against K, one line per L (per-L files, rows in K order).
  std::ostringstream r;
  r << plot_style_lines() << "set xlabel 'K (bits per key)'\nset key bottom left font ',9'\n"
    << "set multiplot layout 1,2 title 'The W = " << run.top_w << " candidates of the index, "
    << run.configs.front().features
    << " query features'\nset title 'recall'\nset yrange [0:1.02]\nset ylabel 'share of query features'\n"
    << "plot " << run.exhaustive_match_recall << " ls 9 title 'correct match, exhaustive top W'";
  const std::vector<uint32_t> ls = distinct_l(run);
  for (size_t i = 0; i < ls.size(); ++i) {
    const std::string f = "'recall.csv' using 1:($2 == " + std::to_string(ls[i]) + " ? $";
    r << ", " << f << "11 : 1/0) with linespoints ls " << i + 1 << " title 'correct match, L=" << ls[i] << "'"
      << ", " << f << "9 : 1/0) with linespoints ls " << i + 1
      << " dt 2 title 'nearest neighbour, L=" << ls[i] << "'";
  }
  r << "\nset title 'cost'\nset logscale y\nset yrange [*:*]\nset ylabel 'bucket entries scanned per "
       "lookup'\nplot ";
  for (size_t i = 0; i < ls.size(); ++i)
    r << (i ? ", " : "") << "'recall.csv' using 1:($2 == " << ls[i] << " ? $15 : 1/0) with linespoints ls "
      << i + 1 << " title 'L=" << ls[i] << "'";
  r << "\nunset multiplot\n";
  if (!render_plot(run.out_dir, "recall", r.str(), 1100, 480, error)) return false;
  made->push_back(plot_file("recall"));
  return true;
}

std::string recommendation(const LshRun& run) {
  std::ostringstream s;
  double best = 0.0;
  for (const LshConfigResult& c : run.configs) best = std::max(best, c.match_recall);
  const LshConfigResult* pick = nullptr;
  for (const LshConfigResult& c : run.configs)
    if (c.match_recall >= best - kRecallSlack &&
        (!pick || c.mean_entries_scanned < pick->mean_entries_scanned))
      pick = &c;
  s << "\n## Recommendation\n\n";
  if (pick) {
    s << "Measured here: **K = " << pick->k << ", L = " << pick->l
      << "** is the cheapest setting (fewest bucket "
      << "entries scanned per lookup, " << num(pick->mean_entries_scanned, 4)
      << ") whose correct-match recall (" << num(100.0 * pick->match_recall, 3) << "%) is within "
      << kRecallSlack * 100.0 << " points of the best measured (" << num(100.0 * best, 3)
      << "%; exhaustive top W: " << num(100.0 * run.exhaustive_match_recall, 3) << "%).\n\n";
  }
  s << "How to pick K and L (eq. 2, section 5 and [10]): the pairs that matter sit at the distance of a "
       "query "
       "feature's correct model feature (the dotted line in collision.png); eq. 2 at that distance should be "
       "high "
       "(L large enough), while at the distance of typical unrelated pairs it must be near zero, or buckets "
       "fill "
       "with features of every model (K large enough). Raising K shrinks buckets (cheaper lookups, fewer LSH "
       "candidates); raising L recovers recall at a linear cost in memory (4 bytes per feature per table) "
       "and "
       "lookups. Because spin images of flat patches are common to every model, a few buckets stay crowded "
       "whatever K is; max_bucket_scan bounds their cost and the truncated share shows how often it bites. "
       "Choose the smallest L, then the largest K, whose correct-match recall stays within a couple of "
       "points "
       "of the exhaustive top W; re-run this experiment when the descriptor or the database changes.\n";
  return s.str();
}

std::string summary(const LshRun& run, const std::vector<std::string>& plots) {
  std::ostringstream s;
  s << "# LSH: eq. 2 and recall of the candidates\n\nCommand: `" << run.command
    << "`\n\n- Models: " << run.source << "\n- Database: " << run.database
    << "\n- Probes: " << run.configs.front().features << " query features from " << run.queries
    << " simulated queries (true model and pose known); " << run.pair_features << " of them paired with all "
    << run.database_features << " database features for the collision curves.\n"
    << "- W = " << run.top_w << " (RecognizerConfig default), max bucket scan " << run.max_bucket_scan
    << "; a correct match is a feature of the true model within Delta = " << run.delta
    << " m of the query feature under the true pose.\n- d_c = " << run.d_c
    << (run.d_c_matches_builder
            ? ""
            : " (**differs from the builder's d_c: the clamped distances here may not be the builder's**)")
    << "; median clamped L1 to the nearest database feature " << run.median_nn_distance
    << ", to the nearest correct feature " << run.median_match_distance << ".\n\n"
    << "## Recall of the W candidates\n\n| K | L | largest bucket | entries scanned | truncated | NN recall "
       "| "
       "top-W recall | correct-match recall | true-model share | us/lookup "
       "|\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const LshConfigResult& c : run.configs)
    s << "| " << c.k << " | " << c.l << (c.is_default ? " (default)" : "") << " | " << c.max_bucket << " | "
      << num(c.mean_entries_scanned, 4) << " | " << num(100.0 * c.truncated_share, 3) << "% | "
      << num(100.0 * c.nn_recall, 3) << "% | " << num(100.0 * c.topw_recall, 3) << "% | "
      << num(100.0 * c.match_recall, 3) << "% | " << num(100.0 * c.true_model_share, 3) << "% | "
      << num(c.us_per_lookup, 3) << " |\n";
  s << "| exhaustive | - | - | " << run.database_features << " | - | 100% | 100% | "
    << num(100.0 * run.exhaustive_match_recall, 3) << "% | "
    << num(100.0 * run.exhaustive_true_model_share, 3) << "% | - |\n\nCorrect-match recall counts the "
    << (run.configs.empty() ? 0 : run.configs.front().features_with_match)
    << " probes that have a correct model feature at all (the query and model basis points are sampled "
       "independently).\n"
    << recommendation(run)
    << "\n## Files\n\n- `collision.csv` (per (K, L) and distance bin: pairs, key collisions, "
       "measured share, eq. 2), `collisions/*.csv` (bins with >= "
    << kMinPairsPerBin << " pairs), `recall.csv`\n"
    << "- Plots:";
  for (const std::string& p : plots) s << " `" << p << "`";
  s << "\n";
  return s.str();
}

}  // namespace

bool write_lsh_report(const LshRun& run, std::string* error) {
  if (run.configs.empty()) {
    *error = "no (K, L) measured";
    return false;
  }
  std::vector<std::string> plots;
  if (!make_output_dir(run.out_dir + "/collisions", error) || !write_csvs(run, error)) return false;
  std::string plot_error;
  if (!write_plots(run, &plots, &plot_error)) plots.push_back("(plots failed: " + plot_error + ")");
  return write_text(run.out_dir + "/summary.md", summary(run, plots), error);
}

}  // namespace spinhash::experiment
