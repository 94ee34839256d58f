#include "recognize/classes.hpp"

#include <cmath>

#include "recognize/class_envelope.hpp"

namespace spinhash {
namespace {

// The class tests of the first class's best model under its pose, then the
// scan's shape against the range of the class's members.
bool first_class_is_confident(const SearchContext& ctx, const Result& result) {
  if (result.class_ranking_count == 0) return false;
  const RankedClass& first = result.class_ranking[0];
  const uint32_t model = result.ranking[first.best_rank].model;
  const RigidPose& pose = ctx.buf.best[model].pose;
  const FeatureSet& fs = ctx.features;
  const ExtentFit fit =
      extent_fit(ctx.query, ctx.db.model(model), pose, hidden_ends(ctx.db, model, fs.ground_band));
  const float density = scan_density(ctx.stats, fit);
  if (!is_class_confident(result, ctx.params, ctx.query.count, fit, density)) return false;
  const ScanShape shape = measure_scan(ctx.query, ctx.db.model(model), pose, fs.top_above_terrain,
                                       fs.terrain_sigma, ctx.params.refine.sigma_surface, density);
  return within_envelope(shape, class_envelope(ctx.db, first.vehicle_class),
                         ctx.params.confidence.max_extent_overhang, ctx.params.classes);
}

}  // namespace

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
  const ConfidenceParams& c = cfg.confidence;
  const ClassesParams& k = cfg.classes;
  const float n = static_cast<float>(features);
  return m.has_pose && features >= k.min_class_features && density >= k.min_class_density &&
         static_cast<float>(m.inliers) >= c.min_inlier_fraction * n &&
         m.score >= c.min_mean_log_likelihood * n &&
         fit.shortfall <= k.class_extent_factor * c.max_extent_shortfall &&
         fit.overhang <= k.class_extent_factor * c.max_extent_overhang &&
         first.score - r.class_ranking[1].score >= c.min_margin * std::sqrt(n);
}

Status classes_stage(SearchContext& ctx) {
  Result& result = ctx.result;
  result.class_ranking = ctx.buf.classes;
  result.class_ranking_count = rank_classes(ctx.db, result, ctx.buf.classes);
  result.class_confident = first_class_is_confident(ctx, result);
  return Status::kOk;
}

}  // namespace spinhash
