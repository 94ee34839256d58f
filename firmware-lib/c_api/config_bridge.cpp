#include "c_api/config_bridge.hpp"

namespace spinhash {

// Both directions list the fields in the same order as the C struct.
void to_c_config(const RecognizerConfig& in, spinhash_config* out) noexcept {
  out->mode = static_cast<int32_t>(in.mode);
  out->seed = in.seed;
  out->max_points = in.max_points;
  out->thin_large_clouds = in.thin_large_clouds ? 1u : 0u;
  out->max_features = in.max_features;
  out->max_models = in.max_models;
  out->max_spin_dims = in.max_spin_dims;
  out->query_basis_spacing = in.query_basis_spacing;
  out->top_w = in.top_w;
  out->top_w_sran = in.top_w_sran;
  out->top_w_sind = in.top_w_sind;
  out->max_bucket_scan = in.max_bucket_scan;
  out->d_min = in.d_min;
  out->theta_min_deg = in.theta_min_deg;
  out->tol_distance = in.tol_distance;
  out->tol_angle_deg = in.tol_angle_deg;
  out->tol_handedness = in.tol_handedness;
  out->sigma = in.sigma;
  out->delta = in.delta;
  out->delta_max = in.delta_max;
  out->eta_max_deg = in.eta_max_deg;
  out->spin_lambda = in.spin_lambda;
  out->min_inlier_fraction = in.min_inlier_fraction;
  out->max_trials = in.max_trials;
  out->sran_trials = in.sran_trials;
  out->max_hypotheses = in.max_hypotheses;
  out->max_pair_checks = in.max_pair_checks;
  out->has_viewpoint = in.has_viewpoint ? 1u : 0u;
  for (int a = 0; a < 3; ++a) out->viewpoint[a] = in.viewpoint[a];
}

bool from_c_config(const spinhash_config& in, RecognizerConfig* out) noexcept {
  if (in.mode != SPINHASH_MODE_BRAN && in.mode != SPINHASH_MODE_SRAN && in.mode != SPINHASH_MODE_SIND)
    return false;
  out->mode = static_cast<Mode>(in.mode);
  out->seed = in.seed;
  out->max_points = in.max_points;
  out->thin_large_clouds = in.thin_large_clouds != 0u;
  out->max_features = in.max_features;
  out->max_models = in.max_models;
  out->max_spin_dims = in.max_spin_dims;
  out->query_basis_spacing = in.query_basis_spacing;
  out->top_w = in.top_w;
  out->top_w_sran = in.top_w_sran;
  out->top_w_sind = in.top_w_sind;
  out->max_bucket_scan = in.max_bucket_scan;
  out->d_min = in.d_min;
  out->theta_min_deg = in.theta_min_deg;
  out->tol_distance = in.tol_distance;
  out->tol_angle_deg = in.tol_angle_deg;
  out->tol_handedness = in.tol_handedness;
  out->sigma = in.sigma;
  out->delta = in.delta;
  out->delta_max = in.delta_max;
  out->eta_max_deg = in.eta_max_deg;
  out->spin_lambda = in.spin_lambda;
  out->min_inlier_fraction = in.min_inlier_fraction;
  out->max_trials = in.max_trials;
  out->sran_trials = in.sran_trials;
  out->max_hypotheses = in.max_hypotheses;
  out->max_pair_checks = in.max_pair_checks;
  out->has_viewpoint = in.has_viewpoint != 0u;
  for (int a = 0; a < 3; ++a) out->viewpoint[a] = in.viewpoint[a];
  return true;
}

}  // namespace spinhash
