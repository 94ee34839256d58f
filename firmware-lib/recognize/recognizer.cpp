// Workspace carving and Recognizer::run: the cloud loaded, then the stages
// (stages.hpp), in one pass or in the cascade's two.
//
// The cascade: the first pass runs the stages at the first_* settings (the
// flight preset's); a confident answer ends the query. Otherwise the full
// pass runs at the config's own settings in the same buffers (the
// workspace is carved for the full pass; the first uses a part of each),
// with carry.enabled starting from the first pass's leading poses
// (carry.hpp). The first
// pass's spin images overwrite its loaded points, so the full pass loads
// the cloud again; its features are its own (another voxel, more of them).
// Each pass's flags are decided by its own calibrated table. The first
// pass's answer stops the query when it is confident (by the first pass's
// table, or by its priors in a database without one) or when the agree
// table (fitted on the first pass's evidence against "the full pass names
// the truth where the first pass does not") says stopping loses no right
// answer; either way its flags stay the first pass's own. A full pass that
// the work cap stops before it poses any model answers with the first
// pass's leading models instead, unflagged like every capped answer.
#include <new>

#include "recognize/carry.hpp"
#include "recognize/classes.hpp"
#include "recognize/config_check.hpp"
#include "recognize/level_evidence.hpp"
#include "recognize/search_context.hpp"
#include "recognize/sparse_search.hpp"
#include "recognize/stages.hpp"
#include "recognize/work_meter.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/presets.hpp"
#include "spinhash/recognizer.hpp"

namespace spinhash {
namespace {

uint32_t candidate_stride(const CandidatesParams& c) {
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
  cap.drops_ground = cfg.ground.enabled && cfg.ground.ground_clearance > 0.0f;
  Status s = b.extractor.init(fp, cap, arena);
  if (s != Status::kOk && s != Status::kWorkspaceTooSmall) return s;
  b.searcher.carve(arena, sparse_bucket_scan(cfg.candidates));
  b.candidate_stride = candidate_stride(cfg.candidates);
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
  Status s = carve(arena, config, db->feature_params(), *b);
  if (s != Status::kOk) return s;
  apply_first_pass(config, &b->first_pass);
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

namespace {

// Clears every flag of an answer at every level (a partial search's answer
// is ranked, never flagged).
void clear_flags(Result* result) {
  result->confident = false;
  result->class_confident = false;
  for (uint32_t l = 0; l < kCalibratedLevels; ++l) result->levels[l].confident = false;
  result->level = AnswerLevel::kNone;
}

// One pass of the stages with `pass`'s settings; `work_before`: what the
// earlier passes spent (the cap, `work_cap`, counts the query's total). Not named run*:
// the instruction scripts toggle callgrind on Recognizer::run*, and a
// nested match would toggle it off.
void recognize_pass(const Database& db, RecognizerBuffers& b, size_t used_bytes, const CloudView& cloud,
                    const ObjectTerrain& terrain, const RecognizerConfig& pass, AnswerPass answer_pass,
                    uint64_t work_before, uint64_t work_cap, Result* result) {
  result->stats.workspace_used = used_bytes;
  SearchContext ctx(db, pass, b, *result);
  ctx.terrain = terrain;
  ctx.work_before = work_before;
  ctx.work_cap = work_cap < pass.max_work ? work_cap : pass.max_work;
  ctx.answer_pass = answer_pass;
  result->status = b.extractor.load(cloud, &ctx.features, &result->stats.extract);
  if (result->status == Status::kOk) result->status = run_stages(ctx);
  CascadeStats& c = result->stats.cascade;
  c.work = work_before + pass_work(result->stats, pass);
  c.work_capped = result->status == Status::kWorkCapReached;
  if (c.work_capped) clear_flags(result);  // a partial search: its answer is never flagged
  keep_leading_poses(ctx);
}

// The agree table says stopping after the first pass loses no right model
// (false without a fitted agree table: the first pass's flag decides alone).
bool full_pass_agrees(const Database& db, const Result& first) {
  const Calibration& c = db.calibration();
  if (first.status != Status::kOk || !c.fitted(AnswerPass::kAgree)) return false;
  return c.confident(AnswerPass::kAgree, AnswerLevel::kModel,
                     first.levels[level_index(AnswerLevel::kModel)].evidence,
                     first.stats.confidence.scan_density);
}

// Keeps the first pass's answer while the full pass reuses the buffers its
// rankings live in: the Result and its first kMaxCarriedPoses models.
void keep_first_answer(RecognizerBuffers& b, const Result& first) {
  b.first_answer = first;
  const uint32_t n = first.ranking_count < kMaxCarriedPoses ? first.ranking_count : kMaxCarriedPoses;
  for (uint32_t i = 0; i < n; ++i) b.first_ranking[i] = first.ranking[i];
  b.first_answer.ranking = b.first_ranking;
  b.first_answer.ranking_count = n;
  if (b.first_answer.group_size > n) b.first_answer.group_size = n;
}

// The full pass was capped before it posed any model: its answer names
// none, the first pass's does.
bool capped_without_pose(const Result& full) {
  return full.status == Status::kWorkCapReached && (full.ranking_count == 0u || !full.ranking[0].has_pose);
}

// Replaces the capped full pass's answer with the kept first pass's: its
// leading models, their class and group rankings rebuilt from them, no
// flag (a partial search's answer); the cascade's counts stay the query's.
void answer_with_first_pass(const Database& db, RecognizerBuffers& b, Result* result) {
  const CascadeStats both = result->stats.cascade;
  *result = b.first_answer;
  result->status = Status::kWorkCapReached;
  if (result->class_ranking_count > 0u) {
    result->class_ranking = b.classes;
    result->class_ranking_count = rank_classes(db, *result, b.classes);
  }
  if (result->group_ranking_count > 0u) {
    result->group_ranking = b.groups;
    result->group_ranking_count = rank_groups(db, *result, b.groups);
  }
  clear_flags(result);
  result->stats.cascade = both;
  result->stats.cascade.answered_by = 0;
}

}  // namespace

Result Recognizer::run(const CloudView& cloud, const ObjectTerrain& terrain) noexcept {
  const uint64_t work_cap = work_cap_;
  Result result;
  if (buffers_ == nullptr) return result;  // kNotOpen
  if (cloud.count > 0 && cloud.xyz_f == nullptr && cloud.xyz_d == nullptr) {
    result.status = Status::kInvalidArgument;
    return result;
  }
  RecognizerBuffers& b = *buffers_;
  b.carried_count = 0;
  uint64_t first_work = 0;
  if (config_.cascade) {
    recognize_pass(*db_, b, used_bytes_, cloud, terrain, b.first_pass, AnswerPass::kFirst, 0, work_cap,
                   &result);
    first_work = result.stats.cascade.work;
    const bool confident = result.status == Status::kOk && result.confident;
    const bool agrees = !confident && full_pass_agrees(*db_, result);
    if (confident || agrees || result.status == Status::kWorkCapReached) {
      result.stats.cascade.stopped_on_agreement = agrees;
      result.stats.cascade.passes = 1;
      result.stats.cascade.answered_by = 0;
      result.stats.cascade.first_work = first_work;
      return result;
    }
    keep_first_answer(b, result);
    result = Result{};
  }
  recognize_pass(*db_, b, used_bytes_, cloud, terrain, config_, calibration_pass(config_), first_work,
                 work_cap, &result);
  CascadeStats& c = result.stats.cascade;
  c.passes = config_.cascade ? 2u : 1u;
  c.answered_by = 1;
  c.first_work = first_work;
  c.full_work = c.work - first_work;
  if (config_.cascade && capped_without_pose(result)) answer_with_first_pass(*db_, b, &result);
  return result;
}

}  // namespace spinhash
