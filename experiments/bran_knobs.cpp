#include "bran_knobs.hpp"

#include "flags/recognizer_flags.hpp"
#include "spinhash/limits.hpp"

namespace spinhash::experiment {

void BranKnobs::apply(RecognizerConfig* cfg) const {
  cfg->candidates.max_bucket_scan = max_bucket_scan;
  cfg->max_features = max_features;
  cfg->transfer.transfer_models = transfer_models;
  cfg->draws.stop_miss_probability = stop_miss_probability;
  cfg->draws.min_hypotheses = min_hypotheses;
  cfg->focus.focus_models = focus_models;
  cfg->draws.lookalike_box_l1 = lookalike_box_l1;
  apply_settings(settings, cfg);
}

void apply_settings(const std::vector<std::string>& settings, RecognizerConfig* cfg) {
  flags::apply_settings(settings, cfg);
}

void add_set_option(CLI::App* cmd, std::vector<std::string>* settings) {
  cmd->add_option("--set", *settings,
                  "STAGE.FIELD=VALUE: any stage parameter (docs/api.md lists them), or a top-level field by "
                  "its name; applied after the other flags (repeatable)")
      ->check(flags::check_setting);
}

void add_bran_knobs(CLI::App* cmd, BranKnobs* knobs) {
  cmd->add_option("--transfer-models", knobs->transfer_models,
                  "BRAN's look-alike pose transfer (0: the paper's BRAN)")
      ->check(CLI::Range(0u, kMaxTransferModels))
      ->capture_default_str();
  cmd->add_option("--stop-miss-probability", knobs->stop_miss_probability,
                  "BRAN's stop on evidence (0: the paper's fixed trials)")
      ->check(CLI::Range(0.0f, 0.5f))
      ->capture_default_str();
  cmd->add_option(
         "--min-hypotheses", knobs->min_hypotheses,
         "BRAN's draws past max_trials while fewer poses were verified (0: the paper's fixed trials)")
      ->capture_default_str();
  cmd->add_option(
         "--focus-models", knobs->focus_models,
         "BRAN's focused search of the leading models on spread candidates or after extended draws (0: off)")
      ->check(CLI::Range(0u, kMaxFocusModels))
      ->capture_default_str();
  cmd->add_option("--lookalike-box", knobs->lookalike_box_l1,
                  "BRAN's look-alike doublets on spread candidates: box L1 bound, m (0: off)")
      ->check(CLI::Range(0.0f, 100.0f))
      ->capture_default_str();
  cmd->add_option("--max-bucket-scan", knobs->max_bucket_scan,
                  "LSH entries scanned per query feature (BRAN, SIND)")
      ->check(CLI::Range(1u, kMaxBucketScan))
      ->capture_default_str();
  cmd->add_option("--max-features", knobs->max_features,
                  "query features kept, evenly thinned above (all modes)")
      ->check(CLI::Range(2u, kMaxQueryFeaturesLimit))
      ->capture_default_str();
  add_set_option(cmd, &knobs->settings);
}

}  // namespace spinhash::experiment
