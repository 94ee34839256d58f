#include "recognize/stages.hpp"

#include "recognize/candidates.hpp"
#include "recognize/classes.hpp"
#include "recognize/confidence.hpp"
#include "recognize/draws.hpp"
#include "recognize/extract.hpp"
#include "recognize/focused_search.hpp"
#include "recognize/ground.hpp"
#include "recognize/pose_transfer.hpp"
#include "recognize/ranking.hpp"
#include "recognize/refinement.hpp"

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

const Stage kStages[] = {
#define SPINHASH_STAGE_ENTRY(id, Name, what) \
  {StageId::id, #id, &id##_stage, [](const StageParams& p) { return switch_of(p.id, 0); }},
    SPINHASH_STAGES(SPINHASH_STAGE_ENTRY)
#undef SPINHASH_STAGE_ENTRY
};
const uint32_t kStageCount = sizeof(kStages) / sizeof(kStages[0]);

Status run_stages(SearchContext& ctx) {
  for (uint32_t i = 0; i < kStageCount; ++i) {
    if (!kStages[i].enabled(ctx.params)) continue;
    const Status s = kStages[i].run(ctx);
    if (s != Status::kOk) return s;
  }
  return Status::kOk;
}

}  // namespace spinhash
