#include "recognize/confidence.hpp"

#include <cmath>

namespace spinhash {
namespace {

// Box faces tested: both ends along x and y, and the top (z up in the model).
constexpr int kTestedFaces = 5;
constexpr float kFar = 3.0e38f;  // beyond any coordinate (no feature yet) and any lead
// The lead over the runner-up that a query whose candidates spread over many
// look-alikes needs, in units of min_margin: the runner-up is then the best
// of many near-identical models, and the best of N noisy scores lies about
// sqrt(2 ln N) spreads above their mean: 2.4 for the 16 focused models
// against 1.2 for the one or two rivals of a query among distinct models.
// With min_margin 0.8 (1.6 here) the 1 000-model scans flag 43 / 37 answers,
// none wrong (34 / 27 at 1.2; docs/results.md 11l).
constexpr float kSpreadMarginFactor = 2.0f;
// The share of max_residual_f that the same query may leave: among hundreds
// of near-identical models most alternatives differ from the first by one
// patch (a longer hood, a lower roof): a weak structure in the residuals.
// On 196 such scans the right answers left F <= 1.55, the two confident
// wrong ones 2.16 and 2.35 (docs/results.md 9k).
constexpr float kSpreadResidualFactor = 0.8f;

// The least density and query features for a confident class.
constexpr float kMinClassDensity = 5.0f;
constexpr uint32_t kMinClassFeatures = 12;
// How far the scan may stop short of the class leader's box ends and top,
// or reach beyond them, in units of max_extent_shortfall and
// max_extent_overhang: members of a class differ by tens of centimetres, a
// vehicle of another class by metres, and a sparse scan's outermost feature
// lies up to a point spacing inside the vehicle's end. Without the
// shortfall test a bus explains every point of a van's sparse scan: 5.4 %
// of the sparse scans of unknown vehicles were confidently of a wrong class,
// most of them a van, truck or APC called a bus.
constexpr float kClassExtentFactor = 2.0f;
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

// 1, or sqrt(kFullModelDensity / density) for a sparser scan; 1 for an
// unmeasured density (0: no pose, no answer to gate).
float density_factor(float density) {
  return density > 0.0f && density < kFullModelDensity ? std::sqrt(kFullModelDensity / density) : 1.0f;
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
  return r.stats.candidates_spread ? kSpreadResidualFactor * cfg.max_residual_f : cfg.max_residual_f;
}

float scan_density(const ExtractStats& s, const ExtentFit& fit) {
  const uint32_t dropped = s.points_nonfinite + s.points_ground;
  const float points = static_cast<float>(s.points_in > dropped ? s.points_in - dropped : 0u);
  return points / (fit.seen_area > kMinTopArea ? fit.seen_area : kMinTopArea);
}

bool dense_enough_for_model(float density) { return density >= kMinModelDensity; }

uint32_t rank_classes(const Database& db, const Result& r, RankedClass* out) {
  uint32_t n = 0;
  for (uint32_t k = 0; k < r.ranking_count; ++k) {
    const uint32_t c = db.model(r.ranking[k].model).vehicle_class;
    uint32_t i = 0;
    while (i < n && out[i].vehicle_class != c) ++i;
    if (i < n) continue;  // ranked already, by a better model
    out[n++] = RankedClass{c, r.ranking[k].score, r.ranking[k].model, k};
  }
  // Insertion sort of at most kVehicleClassCount: best first, ties by class id.
  for (uint32_t i = 1; i < n; ++i)
    for (uint32_t j = i; j > 0; --j) {
      const RankedClass& a = out[j - 1];
      const RankedClass& b = out[j];
      if (a.score > b.score || (a.score == b.score && a.vehicle_class < b.vehicle_class)) break;
      const RankedClass t = out[j - 1];
      out[j - 1] = out[j];
      out[j] = t;
    }
  return n;
}

bool is_class_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                        float density) {
  if (r.class_ranking_count < 2u || cfg.mode == Mode::kSind) return false;
  const RankedClass& first = r.class_ranking[0];
  if (first.vehicle_class == static_cast<uint32_t>(VehicleClass::kUnclassified)) return false;
  const RankedModel& m = r.ranking[first.best_rank];
  const float n = static_cast<float>(features);
  return m.has_pose && features >= kMinClassFeatures && density >= kMinClassDensity &&
         static_cast<float>(m.inliers) >= cfg.min_inlier_fraction * n &&
         m.score >= cfg.min_mean_log_likelihood * n &&
         fit.shortfall <= kClassExtentFactor * cfg.max_extent_shortfall &&
         fit.overhang <= kClassExtentFactor * cfg.max_extent_overhang &&
         first.score - r.class_ranking[1].score >= cfg.min_margin * std::sqrt(n);
}

float lookalike_margin(const Result& r, const RecognizerConfig& cfg) {
  return r.stats.candidates_spread ? kSpreadMarginFactor * cfg.min_margin : cfg.min_margin;
}

float confident_margin(const Result& r, const RecognizerConfig& cfg) {
  const float margin = lookalike_margin(r, cfg) * density_factor(r.stats.scan_density);
  const float c = r.stats.surface_coverage;
  if (!(c < cfg.full_coverage)) return margin;
  if (!(c > 0.0f)) return kFar;  // nothing of the model's top seen: no lead is enough
  const float short_by = cfg.full_coverage / c;
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
  const float n = static_cast<float>(features);
  const float lead = r.ranking_count > 1 ? r.ranking[0].score - r.ranking[1].score : kFar;
  return static_cast<float>(r.ranking[0].inliers) >= cfg.min_inlier_fraction * n &&
         r.ranking[0].score >= cfg.min_mean_log_likelihood * n && r.group_size == 1u &&
         lead >= confident_margin(r, cfg) * std::sqrt(n) && fit.shortfall <= cfg.max_extent_shortfall &&
         fit.overhang <= cfg.max_extent_overhang && residual_f <= residual_limit(r, cfg);
}

}  // namespace spinhash
