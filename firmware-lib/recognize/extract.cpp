#include "recognize/extract.hpp"

#include "descriptor/spin_image.hpp"
#include "recognize/work_meter.hpp"

namespace spinhash {
namespace {

void reset(ModelBest& best) {
  best.pose.rotation.setIdentity();
  best.pose.translation.setZero();
  best.score = 0.0f;
  best.hypotheses = 0;
  best.inliers = 0;
  best.has_score = false;
  best.final_score = false;
}

}  // namespace

Status extract_stage(SearchContext& ctx) {
  RecognizerBuffers& b = ctx.buf;
  FeatureSet& fs = ctx.features;
  const Status s = b.extractor.describe(ctx.hint, ctx.params.extract, ctx.max_features, &fs,
                                        &ctx.stats.extract, extraction_room(ctx));
  if (s == Status::kWorkCapReached) {  // charged, not run: the answering stages see no features
    for (uint32_t m = 0; m < ctx.db.model_count(); ++m) reset(b.best[m]);
    ctx.query = QueryFeatures{};
    return Status::kOk;
  }
  if (s != Status::kOk) return s;
  if (ctx.terrain.top >= 0.0f) {  // the caller's terrain stands for the object ground removal's
    fs.top_above_terrain = ctx.terrain.top;
    fs.terrain_sigma = ctx.terrain.sigma;
    fs.ground_band = ctx.terrain.band;
  }
  if (fs.count < 2u) return Status::kNotEnoughFeatures;
  const float scale = ctx.db.params().spin_quant_scale;
  for (uint32_t f = 0; f < fs.count; ++f)
    quantize_spin(fs.spins + static_cast<size_t>(f) * fs.dims, fs.dims, scale,
                  b.query_spins + static_cast<size_t>(f) * fs.dims);
  for (uint32_t m = 0; m < ctx.db.model_count(); ++m) reset(b.best[m]);
  const uint32_t verify = ctx.params.draws.verify_features;
  ctx.query = QueryFeatures{fs.positions, fs.normals, b.query_spins,
                            fs.count,     fs.dims,    verify < fs.count ? verify : fs.count};
  return Status::kOk;
}

}  // namespace spinhash
