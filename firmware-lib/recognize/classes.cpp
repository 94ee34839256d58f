#include "recognize/classes.hpp"

#include <cmath>

#include "recognize/class_envelope.hpp"
#include "recognize/level_evidence.hpp"
#include "recognize/rank_by_first.hpp"

namespace spinhash {

uint32_t rank_classes(const Database& db, const Result& r, RankedClass* out) {
  const auto class_of = [&db](uint32_t model) { return db.model(model).vehicle_class; };
  return rank_by_first_model(r, class_of, &RankedClass::vehicle_class, kVehicleClassCount, out);
}

bool is_class_confident(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                        float density) {
  if (r.class_ranking_count < 2u) return false;
  const RankedClass& first = r.class_ranking[0];
  if (first.vehicle_class == static_cast<uint32_t>(VehicleClass::kUnclassified)) return false;
  return model_explains_scan(r, cfg, features, r.ranking[first.best_rank], fit, density) &&
         first.score - r.class_ranking[1].score >=
             cfg.confidence.min_margin * std::sqrt(static_cast<float>(features));
}

bool model_explains_scan(const Result& r, const RecognizerConfig& cfg, uint32_t features,
                         const RankedModel& m, const ExtentFit& fit, float density) {
  if (r.class_ranking_count < 2u || cfg.mode == Mode::kSind || !m.has_pose) return false;
  const ConfidenceParams& c = cfg.confidence;
  const ClassesParams& k = cfg.classes;
  const float n = static_cast<float>(features);
  return features >= k.min_class_features && density >= k.min_class_density &&
         static_cast<float>(m.inliers) >= c.min_inlier_fraction * n &&
         m.score >= c.min_mean_log_likelihood * n &&
         fit.shortfall <= k.class_extent_factor * c.max_extent_shortfall &&
         fit.overhang <= k.class_extent_factor * c.max_extent_overhang;
}

Status classes_stage(SearchContext& ctx) {
  Result& result = ctx.result;
  result.class_ranking = ctx.buf.classes;
  result.class_ranking_count = rank_classes(ctx.db, result, ctx.buf.classes);
  // The class, group and vehicle levels against the database's calibrated
  // thresholds (is_class_confident() and the envelope are their prerequisites).
  assess_coarse_levels(ctx, ctx.answer_pass);
  return Status::kOk;
}

}  // namespace spinhash
