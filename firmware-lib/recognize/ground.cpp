#include "recognize/ground.hpp"

namespace spinhash {

Status ground_stage(SearchContext& ctx) {
  return ctx.buf.extractor.drop_ground(ctx.params.ground, &ctx.features, &ctx.stats.ground.points_ground);
}

}  // namespace spinhash
