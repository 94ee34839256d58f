#include "recognize/stages.hpp"

#include "recognize/candidates.hpp"
#include "recognize/carry.hpp"
#include "recognize/classes.hpp"
#include "recognize/confidence.hpp"
#include "recognize/draws.hpp"
#include "recognize/extract.hpp"
#include "recognize/focused_search.hpp"
#include "recognize/ground.hpp"
#include "recognize/pose_transfer.hpp"
#include "recognize/ranking.hpp"
#include "recognize/refinement.hpp"
#include "recognize/work_meter.hpp"

namespace spinhash {
namespace {

// A stage's switch: its params' `enabled` field, or always on.
template <typename P>
auto switch_of(const P& p, int) -> decltype(static_cast<bool>(p.enabled)) {
  return p.enabled;
}
template <typename P>
bool switch_of(const P&, long) {
  return true;
}

}  // namespace

const StageId kStageOrder[] = {
#define SPINHASH_STAGE_ORDER(id, Name, what) StageId::id,
    SPINHASH_STAGES(SPINHASH_STAGE_ORDER)
#undef SPINHASH_STAGE_ORDER
};
const uint32_t kStageCount = sizeof(kStageOrder) / sizeof(kStageOrder[0]);

const char* stage_name(StageId id) {
  switch (id) {
#define SPINHASH_STAGE_NAME(id, Name, what) \
  case StageId::id: return #id;
    SPINHASH_STAGES(SPINHASH_STAGE_NAME)
#undef SPINHASH_STAGE_NAME
  }
  return "?";
}

bool stage_enabled(StageId id, const StageParams& params) {
  switch (id) {
#define SPINHASH_STAGE_SWITCH(id, Name, what) \
  case StageId::id: return switch_of(params.id, 0);
    SPINHASH_STAGES(SPINHASH_STAGE_SWITCH)
#undef SPINHASH_STAGE_SWITCH
  }
  return false;
}

Status run_stage(StageId id, SearchContext& ctx) {
  switch (id) {
#define SPINHASH_STAGE_RUN(id, Name, what) \
  case StageId::id: return id##_stage(ctx);
    SPINHASH_STAGES(SPINHASH_STAGE_RUN)
#undef SPINHASH_STAGE_RUN
  }
  return Status::kInvalidArgument;
}

Status run_stages(SearchContext& ctx) {
  bool capped = false;
  for (uint32_t i = 0; i < kStageCount; ++i) {
    const StageId id = kStageOrder[i];
    if (!stage_enabled(id, ctx.params) || (capped && !stage_answers(id))) continue;
    const Status s = run_stage(id, ctx);
    if (s != Status::kOk) return s;
    capped = capped || work_capped(ctx);
  }
  return capped ? Status::kWorkCapReached : Status::kOk;
}

bool stage_answers(StageId id) {
  return id == StageId::carry || id == StageId::rank || id == StageId::confidence || id == StageId::classes;
}

}  // namespace spinhash
