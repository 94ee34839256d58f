// Workspace carving, the recognize() pipeline and the final ranking.
#include <cmath>
#include <new>

#include "descriptor/spin_image.hpp"
#include "recognize/class_envelope.hpp"
#include "recognize/confidence.hpp"
#include "recognize/search_context.hpp"
#include "recognize/sparse_search.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"
#include "util/angle_math.hpp"
#include "util/heap_sort.hpp"

namespace spinhash {
namespace {

// One range check per kind of SPINHASH_CONFIG_FIELDS; functions, so that a
// field whose range is its type's whole range compiles without "comparison
// is always true".
bool in_range_MODE(Mode v, int lo, int hi) { return static_cast<int>(v) >= lo && static_cast<int>(v) <= hi; }
bool in_range_BOOL(bool, int, int) { return true; }
bool in_range_U32(uint32_t v, uint32_t lo, uint32_t hi) { return v >= lo && v <= hi; }
bool in_range_U64(uint64_t v, uint64_t lo, uint64_t hi) { return v >= lo && v <= hi; }
bool in_range_F32(float v, float lo, float hi) { return v >= lo && v <= hi; }  // false for NaN
bool in_range_VEC3D(const double (&)[3], int, int) { return true; }  // checked with has_viewpoint below

// Every field within its range of SPINHASH_CONFIG_FIELDS, plus the rules
// that join two fields.
bool config_valid(const RecognizerConfig& c) {
  bool ok = true;
#define SPINHASH_CHECK_RANGE(kind, name, lo, hi, flag, help) ok = ok && in_range_##kind(c.name, lo, hi);
  SPINHASH_CONFIG_FIELDS(SPINHASH_CHECK_RANGE)
#undef SPINHASH_CHECK_RANGE
  return ok && c.delta_max >= c.delta &&
         (!c.has_viewpoint ||
          (std::isfinite(c.viewpoint[0]) && std::isfinite(c.viewpoint[1]) && std::isfinite(c.viewpoint[2])));
}

uint32_t candidate_stride(const RecognizerConfig& c) {
  uint32_t w = c.top_w > c.top_w_sran ? c.top_w : c.top_w_sran;
  return w > c.top_w_sind ? w : c.top_w_sind;
}

// Carves every buffer of `b` for `cfg` from `arena`; the single source of the
// workspace layout, run in counting mode by required_workspace_bytes().
Status carve(Arena& arena, const RecognizerConfig& cfg, const FeatureParams& fp, RecognizerBuffers& b) {
  ExtractorCapacity cap;
  cap.max_points = cfg.max_points;
  cap.max_features = cfg.max_features;
  cap.max_spin_dims = cfg.max_spin_dims;
  cap.thin_large_clouds = cfg.thin_large_clouds;
  cap.ground_clearance = cfg.ground_clearance;
  Status s = b.extractor.init(fp, cap, arena);
  if (s != Status::kOk && s != Status::kWorkspaceTooSmall) return s;
  b.searcher.carve(arena, sparse_bucket_scan(cfg.max_bucket_scan));
  b.candidate_stride = candidate_stride(cfg);
  const size_t nf = cfg.max_features;
  b.query_spins = arena.alloc<uint8_t>(nf * cfg.max_spin_dims);
  b.candidates = arena.alloc<Candidate>(nf * b.candidate_stride);
  b.candidate_count = arena.alloc<uint32_t>(nf);
  b.cumulative = arena.alloc<float>(nf);
  b.matches = arena.alloc<int32_t>(nf);
  b.best = arena.alloc<ModelBest>(cfg.max_models);
  b.ranking = arena.alloc<RankedModel>(cfg.max_models);
  b.feature_grid.carve(arena, cfg.max_features);
  b.residuals = arena.alloc<ResidualSample>(nf);
  return arena.overflowed() ? Status::kWorkspaceTooSmall : Status::kOk;
}

// The workspace size planning uses a feature config that passes validation;
// buffer sizes depend only on the capacities in cfg.
FeatureParams sizing_params(const RecognizerConfig& cfg) {
  FeatureParams fp;
  fp.bins_alpha = 1;
  fp.bins_beta = cfg.max_spin_dims <= kMaxSpinBinsPerAxis ? cfg.max_spin_dims : 1u;
  return fp;
}

Pose to_public_pose(const RigidPose& p, const double origin[3]) {
  Pose out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.rotation[3 * r + c] = p.rotation(r, c);
  for (int a = 0; a < 3; ++a) out.translation[a] = static_cast<double>(p.translation[a]) + origin[a];
  return out;
}

void reset(ModelBest& best) {
  best.pose.rotation.setIdentity();
  best.pose.translation.setZero();
  best.score = 0.0f;
  best.hypotheses = 0;
  best.inliers = 0;
  best.has_score = false;
  best.final_score = false;
}

Pose identity_pose() {
  Pose p{};
  p.rotation[0] = p.rotation[4] = p.rotation[8] = 1.0f;
  return p;
}

// The confidence tests of the first model under its pose (confidence.hpp),
// after its stats.surface_coverage; the residuals' structure is measured
// only for an answer that passes the others.
// band: m above the terrain removed with the ground (FeatureSet::ground_band).
bool first_is_confident(const SearchContext& ctx, Result& result, float band) {
  if (result.ranking_count == 0 || !result.ranking[0].has_pose) return false;
  const uint32_t first = result.ranking[0].model;
  const RigidPose& pose = ctx.buf.best[first].pose;
  result.stats.surface_coverage = upward_surface(ctx, first, pose).coverage();
  const ExtentFit fit = extent_fit(ctx.query, ctx.db.model(first), pose, hidden_ends(ctx.db, first, band));
  result.stats.scan_density = scan_density(result.stats.extract, fit);
  if (!dense_enough_for_model(result.stats.scan_density)) return false;
  if (!is_confident(result, ctx.cfg, ctx.query.count, fit, 0.0f)) return false;
  return is_confident(result, ctx.cfg, ctx.query.count, fit, residual_structure(ctx, first, pose));
}

// The class tests of the first class's best model under its pose, then the
// scan's shape against the range of the class's members (class_envelope.hpp).
bool first_class_is_confident(const SearchContext& ctx, const Result& result, const FeatureSet& fs) {
  if (result.class_ranking_count == 0) return false;
  const RankedClass& first = result.class_ranking[0];
  const uint32_t model = result.ranking[first.best_rank].model;
  const RigidPose& pose = ctx.buf.best[model].pose;
  const ExtentFit fit =
      extent_fit(ctx.query, ctx.db.model(model), pose, hidden_ends(ctx.db, model, fs.ground_band));
  const float density = scan_density(result.stats.extract, fit);
  if (!is_class_confident(result, ctx.cfg, ctx.query.count, fit, density)) return false;
  const ScanShape shape = measure_scan(ctx.query, ctx.db.model(model), pose, fs.top_above_terrain,
                                       fs.terrain_sigma, ctx.cfg.sigma_surface, density);
  return within_envelope(shape, class_envelope(ctx.db, first.vehicle_class), ctx.cfg.max_extent_overhang);
}

uint32_t rank_models(const Database& db, RecognizerBuffers& b, const double origin[3]) {
  uint32_t n = 0;
  for (uint32_t m = 0; m < db.model_count(); ++m) {
    const ModelBest& best = b.best[m];
    if (!best.has_score) continue;
    RankedModel& r = b.ranking[n++];
    r.model = m;
    r.score = best.score;
    r.has_pose = best.hypotheses > 0;
    r.pose = r.has_pose ? to_public_pose(best.pose, origin) : identity_pose();
    r.hypotheses = best.hypotheses;
    r.inliers = best.inliers;
  }
  // Best first; equal scores by model index, so the order is fully determined.
  heap_sort(b.ranking, n, [](const RankedModel& x, const RankedModel& y) {
    return x.score > y.score || (x.score == y.score && x.model < y.model);
  });
  return n;
}

}  // namespace

size_t required_workspace_bytes(const RecognizerConfig& config) noexcept {
  if (!config_valid(config)) return 0;
  Arena counter;
  RecognizerBuffers scratch;
  counter.alloc<RecognizerBuffers>(1);
  carve(counter, config, sizing_params(config), scratch);
  return counter.used() + kBufferAlignment;  // slack so a caller's size rounding never bites
}

Status Recognizer::init(const Database* db, const RecognizerConfig& config, void* workspace,
                        size_t workspace_bytes) noexcept {
  buffers_ = nullptr;
  db_ = nullptr;
  if (db == nullptr || !db->is_open() || workspace == nullptr || !config_valid(config))
    return Status::kInvalidArgument;
  if (reinterpret_cast<uintptr_t>(workspace) % kBufferAlignment != 0) return Status::kMisalignedBuffer;
  if (db->model_count() > config.max_models) return Status::kDatabaseTooLarge;
  if (db->spin_dims() > config.max_spin_dims) return Status::kInvalidArgument;
  Arena arena(workspace, workspace_bytes);
  RecognizerBuffers* b = arena.alloc<RecognizerBuffers>(1);
  if (b == nullptr) return Status::kWorkspaceTooSmall;
  new (b) RecognizerBuffers();
  FeatureParams fp = db->feature_params();
  if (config.query_basis_spacing > 0.0f) fp.basis_spacing = config.query_basis_spacing;
  if (config.query_cloud_voxel > 0.0f) fp.cloud_voxel = config.query_cloud_voxel;
  Status s = carve(arena, config, fp, *b);
  if (s != Status::kOk) return s;
  db_ = db;
  config_ = config;
  used_bytes_ = arena.used();
  buffers_ = b;
  return Status::kOk;
}

Result Recognizer::recognize(const float* xyz, uint32_t count) noexcept {
  return recognize(xyz, count, ObjectTerrain{});
}

Result Recognizer::recognize(const float* xyz, uint32_t count, const ObjectTerrain& terrain) noexcept {
  CloudView cloud;
  cloud.xyz_f = xyz;
  cloud.count = count;
  return run(cloud, terrain);
}

Result Recognizer::recognize(const double* xyz, uint32_t count) noexcept {
  CloudView cloud;
  cloud.xyz_d = xyz;
  cloud.count = count;
  return run(cloud, ObjectTerrain{});
}

Result Recognizer::run(const CloudView& cloud, const ObjectTerrain& terrain) noexcept {
  Result result;
  if (buffers_ == nullptr) return result;  // kNotOpen
  if (cloud.count > 0 && cloud.xyz_f == nullptr && cloud.xyz_d == nullptr) {
    result.status = Status::kInvalidArgument;
    return result;
  }
  RecognizerBuffers& b = *buffers_;
  result.stats.workspace_used = used_bytes_;
  OrientationHint hint;
  hint.has_viewpoint = config_.has_viewpoint;
  for (int a = 0; a < 3; ++a) hint.viewpoint[a] = config_.viewpoint[a];
  FeatureSet fs;
  result.status = b.extractor.extract(cloud, hint, &fs, &result.stats.extract);
  if (result.status != Status::kOk) return result;
  if (terrain.top >= 0.0f) {  // the caller's terrain stands for the object ground removal's
    fs.top_above_terrain = terrain.top;
    fs.terrain_sigma = terrain.sigma;
    fs.ground_band = terrain.band;
  }
  result.stats.features = fs.count;
  if (fs.count < 2u) {
    result.status = Status::kNotEnoughFeatures;
    return result;
  }
  const float scale = db_->params().spin_quant_scale;
  for (uint32_t f = 0; f < fs.count; ++f)
    quantize_spin(fs.spins + static_cast<size_t>(f) * fs.dims, fs.dims, scale,
                  b.query_spins + static_cast<size_t>(f) * fs.dims);
  for (uint32_t m = 0; m < db_->model_count(); ++m) reset(b.best[m]);

  SearchContext ctx{
      *db_,
      config_,
      b,
      QueryFeatures{fs.positions, fs.normals, b.query_spins, fs.count, fs.dims,
                    config_.verify_features < fs.count ? config_.verify_features : fs.count},
      make_likelihood_params(config_, *db_),
      DoubletTolerance{config_.tol_distance, deg_to_rad(config_.tol_angle_deg), config_.tol_handedness},
      config_.d_min,
      deg_to_rad(config_.theta_min_deg),
      std::cos(deg_to_rad(config_.max_tilt_deg)),
      result.stats,
      Pcg32(config_.seed),
      nullptr,
      EvidenceState{}};
  {
    const ExtractStats& e = result.stats.extract;
    const uint32_t dropped = e.points_nonfinite + e.points_ground;
    const float density = footprint_density(ctx.query, e.points_in > dropped ? e.points_in - dropped : 0u);
    ctx.trial_scale = trial_scale(density);
    b.searcher.set_scan(bucket_scan(config_.max_bucket_scan, config_.max_features, density, fs.count));
  }
  switch (config_.mode) {
    case Mode::kBran: run_bran(ctx); break;
    case Mode::kSran: run_sran(ctx); break;
    case Mode::kSind: run_sind(ctx); break;
  }
  if (config_.mode != Mode::kSind) finalise_scores(ctx, config_.refine_poses);
  result.ranking = b.ranking;
  result.ranking_count = rank_models(*db_, b, fs.origin);
  result.group_size = lookalike_group_size(result, config_, fs.count);
  order_twins_by_residuals(ctx, b.ranking, result.group_size);
  result.confident = first_is_confident(ctx, result, fs.ground_band);
  result.class_ranking = b.classes;
  result.class_ranking_count = rank_classes(*db_, result, b.classes);
  result.class_confident = first_class_is_confident(ctx, result, fs);
  return result;
}

}  // namespace spinhash
