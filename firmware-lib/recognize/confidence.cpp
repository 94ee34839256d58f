#include "recognize/confidence.hpp"

#include <cmath>

#include "recognize/level_evidence.hpp"
#include "recognize/residual_structure.hpp"
#include "recognize/visible_surface.hpp"
#include "util/far.hpp"

namespace spinhash {
namespace {

// Box faces tested: both ends along x and y, and the top (z up in the model).
constexpr int kTestedFaces = 5;
constexpr float kMinTopArea = 0.25f;  // m^2: a degenerate box counts as this

// The query's two outermost features on each side of every axis, in the
// model's frame: the outermost says how far the scan reaches, the second
// how far it overhangs (one stray feature, a noise spike or a ground
// remnant beside the vehicle, does not count).
struct Outermost {
  Eigen::Vector3f lo[2], hi[2];  // [0] outermost, [1] second
  Outermost() {
    for (int k = 0; k < 2; ++k)
      lo[k] = Eigen::Vector3f::Constant(kFar), hi[k] = Eigen::Vector3f::Constant(-kFar);
  }
  void add(const Eigen::Vector3f& x) {
    for (int a = 0; a < 3; ++a) {
      if (x[a] < lo[1][a]) lo[1][a] = x[a] < lo[0][a] ? lo[0][a] : x[a];
      if (x[a] < lo[0][a]) lo[0][a] = x[a];
      if (x[a] > hi[1][a]) hi[1][a] = x[a] > hi[0][a] ? hi[0][a] : x[a];
      if (x[a] > hi[0][a]) hi[0][a] = x[a];
    }
  }
  // m^2 of the box's top within the outermost features' x and y span.
  float seen_area(const blob::ModelRecord& m) const {
    float area = 1.0f;
    for (int a = 0; a < 2; ++a) {
      const float from = lo[0][a] > m.bbox_min[a] ? lo[0][a] : m.bbox_min[a];
      const float to = hi[0][a] < m.bbox_max[a] ? hi[0][a] : m.bbox_max[a];
      area *= to > from ? to - from : 0.0f;
    }
    return area;
  }
  // Per tested face, how far the k-th outermost feature stops short of it
  // (> 0) or reaches past it (< 0).
  void gaps(const blob::ModelRecord& m, int k, float* gap) const {
    gap[0] = lo[k][0] - m.bbox_min[0];
    gap[1] = m.bbox_max[0] - hi[k][0];
    gap[2] = lo[k][1] - m.bbox_min[1];
    gap[3] = m.bbox_max[1] - hi[k][1];
    gap[4] = m.bbox_max[2] - hi[k][2];
  }
};

// 1, or sqrt(full_model_density / density) for a sparser scan; 1 for an
// unmeasured density (0: no pose, no answer to gate).
float density_factor(const ConfidenceParams& c, float density) {
  return density > 0.0f && density < c.full_model_density ? std::sqrt(c.full_model_density / density) : 1.0f;
}

}  // namespace

HiddenEnds hidden_ends(const Database& db, uint32_t model, float band) {
  HiddenEnds h;
  const blob::ModelRecord& r = db.model(model);
  if (!(band > 0.0f) || r.feature_count == 0u) return h;
  const float* p = db.positions() + 3u * static_cast<size_t>(r.first_feature);
  const float cut = r.bbox_min[2] + band;
  Outermost all, above;
  for (uint32_t f = 0; f < r.feature_count; ++f) {
    const Eigen::Map<const Eigen::Vector3f> x(p + 3u * f);
    all.add(x);
    if (x[2] > cut) above.add(x);
  }
  if (above.lo[0][0] > above.hi[0][0]) return h;  // nothing above the band
  h.face[0] = above.lo[0][0] - all.lo[0][0];
  h.face[1] = all.hi[0][0] - above.hi[0][0];
  h.face[2] = above.lo[0][1] - all.lo[0][1];
  h.face[3] = all.hi[0][1] - above.hi[0][1];
  return h;
}

ExtentFit extent_fit(const QueryFeatures& query, const blob::ModelRecord& model, const RigidPose& pose,
                     const HiddenEnds& hidden) {
  ExtentFit fit;
  if (query.count == 0) return fit;
  Outermost out;
  const Eigen::Matrix3f to_model = pose.rotation.transpose();
  for (uint32_t f = 0; f < query.count; ++f)
    out.add(to_model * (Eigen::Map<const Eigen::Vector3f>(query.positions + 3u * f) - pose.translation));
  float reach[kTestedFaces], second[kTestedFaces];
  out.gaps(model, 0, reach);
  out.gaps(model, 1, second);
  for (int i = 0; i < 4; ++i) reach[i] -= hidden.face[i];
  fit.seen_area = out.seen_area(model);
  for (int i = 0; i < kTestedFaces; ++i) {
    fit.shortfall = reach[i] > fit.shortfall ? reach[i] : fit.shortfall;
    fit.overhang = -second[i] > fit.overhang ? -second[i] : fit.overhang;
  }
  return fit;
}

float residual_limit(const Result& r, const RecognizerConfig& cfg) {
  const ConfidenceParams& c = cfg.confidence;
  return r.stats.candidates.spread ? c.spread_residual_factor * c.max_residual_f : c.max_residual_f;
}

float scan_density(const RecognitionStats& s, const ExtentFit& fit) {
  const uint32_t dropped = s.extract.points_nonfinite + s.ground.points_ground;
  const float points = static_cast<float>(s.extract.points_in > dropped ? s.extract.points_in - dropped : 0u);
  return points / (fit.seen_area > kMinTopArea ? fit.seen_area : kMinTopArea);
}

bool dense_enough_for_model(const RecognizerConfig& cfg, float density) {
  return density >= cfg.confidence.min_model_density;
}

float lookalike_margin(const Result& r, const RecognizerConfig& cfg) {
  const ConfidenceParams& c = cfg.confidence;
  return r.stats.candidates.spread ? c.spread_margin_factor * c.min_margin : c.min_margin;
}

float confident_margin(const Result& r, const RecognizerConfig& cfg) {
  const ConfidenceParams& c = cfg.confidence;
  const float margin = lookalike_margin(r, cfg) * density_factor(c, r.stats.confidence.scan_density);
  const float cov = r.stats.confidence.surface_coverage;
  if (!(cov < c.full_coverage)) return margin;
  if (!(cov > 0.0f)) return kFar;  // nothing of the model's top seen: no lead is enough
  const float short_by = c.full_coverage / cov;
  return margin * short_by * short_by;
}

uint32_t lookalike_group_size(const Result& r, const RecognizerConfig& cfg, uint32_t features) {
  if (r.ranking_count == 0) return 0;
  if (cfg.mode == Mode::kSind) return 1;
  uint32_t k = 1;
  const float within = lookalike_margin(r, cfg) * std::sqrt(static_cast<float>(features));
  while (k < r.ranking_count && r.ranking[0].score - r.ranking[k].score < within) ++k;
  return k;
}

bool is_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                  float residual_f) {
  if (r.ranking_count == 0 || !r.ranking[0].has_pose) return false;
  const ConfidenceParams& c = cfg.confidence;
  const float n = static_cast<float>(features);
  const float lead = r.ranking_count > 1 ? r.ranking[0].score - r.ranking[1].score : kFar;
  return static_cast<float>(r.ranking[0].inliers) >= c.min_inlier_fraction * n &&
         r.ranking[0].score >= c.min_mean_log_likelihood * n && r.group_size == 1u &&
         lead >= confident_margin(r, cfg) * std::sqrt(n) && fit.shortfall <= c.max_extent_shortfall &&
         fit.overhang <= c.max_extent_overhang && residual_f <= residual_limit(r, cfg);
}

Status confidence_stage(SearchContext& ctx) {
  Result& result = ctx.result;
  result.confident = false;
  result.levels[level_index(AnswerLevel::kModel)] = LevelAnswer{};
  if (result.ranking_count == 0 || !result.ranking[0].has_pose) return Status::kOk;
  const uint32_t first = result.ranking[0].model;
  const RigidPose& pose = ctx.buf.best[first].pose;
  ConfidenceStats& st = ctx.stats.confidence;
  st.surface_coverage = upward_surface(ctx, first, pose).coverage();
  const float band = ctx.features.ground_band;  // m above the terrain removed with the ground
  const ExtentFit fit = extent_fit(ctx.query, ctx.db.model(first), pose, hidden_ends(ctx.db, first, band));
  st.scan_density = scan_density(ctx.stats, fit);
  // The model level's evidence against the database's calibrated threshold
  // for this density (the parameters above are its priors and prerequisites).
  assess_model_level(ctx, fit, ctx.answer_pass);
  return Status::kOk;
}

}  // namespace spinhash
