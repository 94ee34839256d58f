#include "pipeline/recognizer_flags.hpp"

#include <map>

#include "spinhash/limits.hpp"

namespace spinhash::pipeline {

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::kBran: return "bran";
    case Mode::kSran: return "sran";
    case Mode::kSind: return "sind";
  }
  return "?";
}

void add_recognizer_flags(CLI::App* cmd, RecognizerConfig* c) {
  std::map<std::string, Mode> modes{{"bran", Mode::kBran}, {"sran", Mode::kSran}, {"sind", Mode::kSind}};
  cmd->add_option("--mode", c->mode, "bran (batch RANSAC), sran (per-model RANSAC) or sind (LSH voting)")
      ->transform(CLI::CheckedTransformer(modes, CLI::ignore_case));
  cmd->add_option("--seed", c->seed, "sampling seed")->capture_default_str();
  cmd->add_option("--max-points", c->max_points, "largest cloud accepted")
      ->check(CLI::Range(1u, kMaxQueryPointsLimit))->capture_default_str();
  cmd->add_option("--max-features", c->max_features, "query basis points kept")
      ->check(CLI::Range(2u, kMaxQueryFeaturesLimit))->capture_default_str();
  cmd->add_option("--max-models", c->max_models, "models the workspace supports")
      ->check(CLI::Range(1u, kMaxModels))->capture_default_str();
  cmd->add_option("--query-spacing", c->query_basis_spacing, "query basis point spacing, m (0: the database's)")
      ->capture_default_str();
  cmd->add_option("--ground-clearance", c->ground_clearance,
                  "m of level ground dropped from the bottom of the cloud, z up (0: keep the ground)")
      ->check(CLI::Range(0.0f, kMaxGroundClearance))->capture_default_str();
  cmd->add_option("--verify-features", c->verify_features, "query features scored per hypothesis")->capture_default_str();
  cmd->add_flag("!--no-refine", c->refine_poses, "skip the least-squares pose refinement");
  cmd->add_option("--tol-angle", c->tol_angle_deg, "doublet angle tolerance, degrees")->capture_default_str();
  cmd->add_option("--tol-distance", c->tol_distance, "doublet distance tolerance, m")->capture_default_str();
  cmd->add_option("-W,--top-w", c->top_w, "W: candidates per query feature (BRAN)")
      ->check(CLI::Range(1u, kMaxCandidates))->capture_default_str();
  cmd->add_option("--transfer-models", c->transfer_models,
                  "look-alikes each leading pose is also tried on (BRAN; 0: off, the paper's BRAN)")
      ->check(CLI::Range(0u, kMaxTransferModels))->capture_default_str();
  cmd->add_option("--top-w-sran", c->top_w_sran, "W per model (SRAN)")->check(CLI::Range(1u, kMaxCandidates))->capture_default_str();
  cmd->add_option("--top-w-sind", c->top_w_sind, "W (SIND)")->check(CLI::Range(1u, kMaxCandidates))->capture_default_str();
  cmd->add_option("--max-bucket-scan", c->max_bucket_scan, "LSH entries scanned per query feature")->capture_default_str();
  cmd->add_option("--trials", c->max_trials, "doublet draws (BRAN)")->capture_default_str();
  cmd->add_option("--sran-trials", c->sran_trials, "doublet draws per model (SRAN)")->capture_default_str();
  cmd->add_option("--max-hypotheses", c->max_hypotheses, "poses verified (BRAN total, SRAN per model)")->capture_default_str();
  cmd->add_option("--max-pair-checks", c->max_pair_checks, "candidate pairs through the cascade")->capture_default_str();
  cmd->add_option("--sigma", c->sigma, "sigma of eq. 5, m")->capture_default_str();
  cmd->add_option("--delta", c->delta, "Delta of eq. 5, m")->capture_default_str();
  cmd->add_option("--delta-max", c->delta_max, "Delta_max of eq. 5, m")->capture_default_str();
  cmd->add_option("--eta-max", c->eta_max_deg, "eta_max of eq. 6, degrees")->capture_default_str();
  cmd->add_option("--d-min", c->d_min, "d_min of eq. 3, m")->capture_default_str();
  cmd->add_option("--theta-min", c->theta_min_deg, "theta_min of eq. 3, degrees")->capture_default_str();
}

}  // namespace spinhash::pipeline
