#include "recognize/search_context.hpp"

#include <cmath>

#include "util/angle_math.hpp"

namespace spinhash {

SearchContext::SearchContext(const Database& database, const RecognizerConfig& pass,
                             RecognizerBuffers& buffers, Result& answer)
    : db(database),
      params(pass),
      mode(pass.mode),
      max_features(pass.max_features),
      buf(buffers),
      result(answer),
      stats(answer.stats),
      likelihood(make_likelihood_params(pass, database)),
      tolerance{pass.draws.tol_distance, deg_to_rad(pass.draws.tol_angle_deg), pass.draws.tol_handedness},
      d_min(pass.draws.d_min),
      theta_min(deg_to_rad(pass.draws.theta_min_deg)),
      min_up_z(std::cos(deg_to_rad(pass.draws.max_tilt_deg))),
      rng(pass.seed) {
  hint.has_viewpoint = pass.has_viewpoint;
  for (int a = 0; a < 3; ++a) hint.viewpoint[a] = pass.viewpoint[a];
}

OrientedPoint SearchContext::query_point(uint32_t f) const {
  const float* p = query.positions + 3u * f;
  const float* n = query.normals + 3u * f;
  return OrientedPoint{Eigen::Vector3f(p[0], p[1], p[2]), Eigen::Vector3f(n[0], n[1], n[2])};
}

OrientedPoint SearchContext::model_point(uint32_t f) const { return model_feature_point(db, f); }

}  // namespace spinhash
