#include "recognize/level_evidence.hpp"

#include <cmath>

#include "recognize/classes.hpp"
#include "recognize/rank_by_first.hpp"
#include "recognize/residual_structure.hpp"
#include "spinhash/vehicle_class.hpp"

namespace spinhash {
namespace {

// The settings with no margin: what is_confident() and
// is_class_confident() then test are the prerequisites alone.
RecognizerConfig without_margin(const RecognizerConfig& cfg) {
  RecognizerConfig c = cfg;
  c.confidence.min_margin = 0.0f;
  return c;
}

// confident_margin()'s factors but density: the margin of a unit min_margin
// for a scan whose density is not measured.
float shape_factor(const Result& r, const RecognizerConfig& cfg) {
  Result unit = r;
  unit.stats.confidence.scan_density = 0.0f;
  RecognizerConfig c = cfg;
  c.confidence.min_margin = 1.0f;
  return confident_margin(unit, c);
}

float lead_per_feature(float first, float second, uint32_t features) {
  return (first - second) / std::sqrt(static_cast<float>(features));
}

float span(float lo, float hi) { return hi > lo ? hi - lo : 0.0f; }

}  // namespace

float model_evidence(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                     float residual_f) {
  if (features == 0u || !is_confident(r, without_margin(cfg), features, fit, residual_f)) return kNoEvidence;
  if (r.ranking_count < 2u) return kUnopposed;
  const float shape = shape_factor(r, cfg);
  if (!(shape > 0.0f)) return kNoEvidence;
  return lead_per_feature(r.ranking[0].score, r.ranking[1].score, features) / shape;
}

float class_evidence(const Result& r, const RecognizerConfig& cfg, uint32_t features, const ExtentFit& fit,
                     float density, bool within_envelope) {
  if (features == 0u || !within_envelope ||
      !is_class_confident(r, without_margin(cfg), features, fit, density))
    return kNoEvidence;
  return lead_per_feature(r.class_ranking[0].score, r.class_ranking[1].score, features);
}

uint32_t rank_groups(const Database& db, const Result& r, RankedGroup* out) {
  const auto group_of = [&db](uint32_t model) { return static_cast<uint32_t>(model_group(db.model(model))); };
  return rank_by_first_model(r, group_of, &RankedGroup::group, kVehicleGroupCount, out);
}

MemberFit member_fit(const SearchContext& ctx, uint32_t model) {
  const blob::ModelRecord& record = ctx.db.model(model);
  const RigidPose& pose = ctx.buf.best[model].pose;
  const FeatureSet& fs = ctx.features;
  MemberFit m;
  m.fit = extent_fit(ctx.query, record, pose, hidden_ends(ctx.db, model, fs.ground_band));
  m.density = scan_density(ctx.result.stats, m.fit);
  m.shape = measure_scan(ctx.query, record, pose, fs.top_above_terrain, fs.terrain_sigma,
                         ctx.params.refine.sigma_surface, m.density);
  return m;
}

float group_evidence(const SearchContext& ctx, uint32_t known_rank, const MemberFit& known) {
  const Result& r = ctx.result;
  const Database& db = ctx.db;
  const RecognizerConfig& cfg = ctx.params;
  const uint32_t n = ctx.query.count;
  if (n == 0u || r.group_ranking_count == 0u) return kNoEvidence;
  const uint32_t group = r.group_ranking[0].group;
  if (group == static_cast<uint32_t>(VehicleGroup::kNone)) return kNoEvidence;
  const ClassEnvelope envelope = group_envelope(db, group);
  uint32_t tried = 0;
  for (uint32_t i = 0; i < r.ranking_count && tried < cfg.classes.group_fit_models; ++i) {
    const RankedModel& m = r.ranking[i];
    if (!m.has_pose || static_cast<uint32_t>(model_group(db.model(m.model))) != group) continue;
    ++tried;
    const MemberFit member = i == known_rank ? known : member_fit(ctx, m.model);
    if (!model_explains_scan(r, cfg, n, m, member.fit, member.density) ||
        !within_envelope(member.shape, envelope, cfg.confidence.max_extent_overhang, cfg.classes))
      continue;
    if (r.group_ranking_count < 2u) return kUnopposed;
    return lead_per_feature(r.group_ranking[0].score, r.group_ranking[1].score, n);
  }
  return kNoEvidence;
}

float vehicle_evidence(const Result& r, uint32_t features, const ExtentFit& fit,
                       const blob::ModelRecord& model) {
  if (features == 0u || r.ranking_count == 0u || !r.ranking[0].has_pose) return kNoEvidence;
  const float top = span(model.bbox_min[0], model.bbox_max[0]) * span(model.bbox_min[1], model.bbox_max[1]);
  if (!(top > 0.0f) || !(fit.seen_area > 0.0f)) return kNoEvidence;
  const float seen = fit.seen_area < top ? fit.seen_area / top : 1.0f;
  return r.ranking[0].score / static_cast<float>(features) + std::log(seen);
}

bool prior_confident(AnswerLevel level, float evidence, float density, const RecognizerConfig& cfg) {
  const ConfidenceParams& c = cfg.confidence;
  switch (level) {
    case AnswerLevel::kModel: {
      if (!dense_enough_for_model(cfg, density)) return false;
      const float sparse =
          density > 0.0f && density < c.full_model_density ? std::sqrt(c.full_model_density / density) : 1.0f;
      return evidence >= c.min_margin * sparse;
    }
    case AnswerLevel::kClass:
    case AnswerLevel::kGroup: return evidence >= c.min_margin;
    case AnswerLevel::kVehicle: return evidence >= c.min_mean_log_likelihood;
    default: return false;
  }
}

bool level_confident(const Database& db, AnswerPass pass, AnswerLevel level, float evidence, float density,
                     const RecognizerConfig& cfg) {
  const Calibration& c = db.calibration();
  return c.fitted(pass) ? c.confident(pass, level, evidence, density)
                        : prior_confident(level, evidence, density, cfg);
}

namespace {

// The group a ranked class answers in: its own, or for a class in no group,
// its best model's own group.
uint32_t class_group_in(const Database& db, const RankedClass& c) {
  return static_cast<uint32_t>(vehicle_group_of(c.vehicle_class, db.model(c.model).vehicle_group));
}

}  // namespace

AnswerLevel answer_level(const Database& db, const LevelAnswer* levels, const AnswerLeaders& first) {
  const auto confident = [levels](AnswerLevel l) { return levels[level_index(l)].confident; };
  if (!confident(AnswerLevel::kVehicle)) return AnswerLevel::kNone;
  if (!confident(AnswerLevel::kGroup) || first.group == nullptr) return AnswerLevel::kVehicle;
  if (!confident(AnswerLevel::kClass) || first.vehicle_class == nullptr ||
      class_group_in(db, *first.vehicle_class) != first.group->group)
    return AnswerLevel::kGroup;
  if (!confident(AnswerLevel::kModel) || first.model == nullptr ||
      db.model(first.model->model).vehicle_class != first.vehicle_class->vehicle_class)
    return AnswerLevel::kClass;
  return AnswerLevel::kModel;
}

AnswerLevel answer_level(const Database& db, const Result& r) {
  AnswerLeaders first;
  first.model = r.ranking_count > 0u ? r.ranking : nullptr;
  first.vehicle_class = r.class_ranking_count > 0u ? r.class_ranking : nullptr;
  first.group = r.group_ranking_count > 0u ? r.group_ranking : nullptr;
  return answer_level(db, r.levels, first);
}

void assess_model_level(const SearchContext& ctx, const ExtentFit& fit, AnswerPass pass) {
  Result& r = ctx.result;
  LevelAnswer& model = r.levels[level_index(AnswerLevel::kModel)];
  model = LevelAnswer{};
  const uint32_t n = ctx.query.count;
  if (r.ranking_count > 0u && r.ranking[0].has_pose) {
    model.evidence =
        model_evidence(r, ctx.params, n, fit, 0.0f);  // the residuals only for what passes the rest
    if (model.evidence > kNoEvidence) {
      const uint32_t first = r.ranking[0].model;
      model.evidence =
          model_evidence(r, ctx.params, n, fit, residual_structure(ctx, first, ctx.buf.best[first].pose));
    }
  }
  model.confident = level_confident(ctx.db, pass, AnswerLevel::kModel, model.evidence,
                                    r.stats.confidence.scan_density, ctx.params);
  r.confident = model.confident;
}

void assess_coarse_levels(const SearchContext& ctx, AnswerPass pass) {
  Result& r = ctx.result;
  const Database& db = ctx.db;
  const RecognizerConfig& cfg = ctx.params;
  const FeatureSet& fs = ctx.features;
  const uint32_t n = ctx.query.count;
  r.group_ranking = ctx.buf.groups;
  r.group_ranking_count = rank_groups(db, r, ctx.buf.groups);
  LevelAnswer& vehicle = r.levels[level_index(AnswerLevel::kVehicle)];
  LevelAnswer& group = r.levels[level_index(AnswerLevel::kGroup)];
  LevelAnswer& vclass = r.levels[level_index(AnswerLevel::kClass)];
  vehicle = group = vclass = LevelAnswer{};
  // The first class's best model (the class leader, most often the first
  // model): measured once, for the class level and, at its rank, the
  // vehicle and group levels.
  constexpr uint32_t kNoRank = UINT32_MAX;
  uint32_t leader_rank = kNoRank;
  MemberFit leader;
  if (r.class_ranking_count > 0u && r.ranking[r.class_ranking[0].best_rank].has_pose) {
    leader_rank = r.class_ranking[0].best_rank;
    leader = member_fit(ctx, r.ranking[leader_rank].model);
    vclass.evidence =
        class_evidence(r, cfg, n, leader.fit, leader.density,
                       within_envelope(leader.shape, class_envelope(db, r.class_ranking[0].vehicle_class),
                                       cfg.confidence.max_extent_overhang, cfg.classes));
  }
  group.evidence = group_evidence(ctx, leader_rank, leader);
  // A vehicle is what a posed member of the first group explains (the group
  // level's prerequisites, not its lead): a vehicle's size and bulk alone,
  // which sheds, heaps and containers share, do not make one.
  if (group.evidence > kNoEvidence && r.ranking_count > 0u && r.ranking[0].has_pose) {
    const uint32_t first = r.ranking[0].model;
    const ExtentFit fit = leader_rank == 0u ? leader.fit
                                            : extent_fit(ctx.query, db.model(first), ctx.buf.best[first].pose,
                                                         hidden_ends(db, first, fs.ground_band));
    vehicle.evidence = vehicle_evidence(r, n, fit, db.model(first));
  }
  const float density = r.stats.confidence.scan_density;
  vehicle.confident = level_confident(db, pass, AnswerLevel::kVehicle, vehicle.evidence, density, cfg);
  group.confident = level_confident(db, pass, AnswerLevel::kGroup, group.evidence, density, cfg);
  vclass.confident = level_confident(db, pass, AnswerLevel::kClass, vclass.evidence, density, cfg);
  r.class_confident = vclass.confident;
  r.level = answer_level(db, r);
}

}  // namespace spinhash
