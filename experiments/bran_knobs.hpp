// BRAN's additions to the paper that the experiments switch (--transfer-models,
// --stop-miss-probability, --min-hypotheses, --focus-models, --lookalike-box), so one run can compare them
// with the paper's BRAN; the LSH scan bound (--max-bucket-scan) that sets
// the index's cost; the query features kept (--max-features) that set a
// large vehicle's; any other field by its key (--set STAGE.FIELD=VALUE:
// levers swept without a flag of their own, scripts/flight-levers.sh).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "spinhash/config.hpp"

namespace spinhash::experiment {

struct BranKnobs {
  uint32_t transfer_models = TransferParams{}.transfer_models;
  float stop_miss_probability = DrawsParams{}.stop_miss_probability;
  uint32_t min_hypotheses = DrawsParams{}.min_hypotheses;
  uint32_t focus_models = FocusParams{}.focus_models;
  float lookalike_box_l1 = DrawsParams{}.lookalike_box_l1;
  uint32_t max_bucket_scan = CandidatesParams{}.max_bucket_scan;
  uint32_t max_features = RecognizerConfig{}.max_features;
  std::vector<std::string> settings;  // --set KEY=VALUE, any field, applied last
  void apply(RecognizerConfig* cfg) const;
};

void add_bran_knobs(CLI::App* cmd, BranKnobs* knobs);

// --set KEY=VALUE (repeatable) alone, for experiments without the knobs
// above (scene); apply_settings() assigns them in order.
void add_set_option(CLI::App* cmd, std::vector<std::string>* settings);
void apply_settings(const std::vector<std::string>& settings, RecognizerConfig* cfg);

}  // namespace spinhash::experiment
