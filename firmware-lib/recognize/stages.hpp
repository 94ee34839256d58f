// The recognizer's stages (stage_fields.h, SPINHASH_STAGES), run in order
// over one SearchContext: a pass. Each stage reads its parameters from the
// pass's config (ctx.params.<id>), counts in its block of the statistics
// (stats.<id>) and may stop the pass with a status (the ground and extract
// stages, on a cloud without enough features). A stage with an `enabled`
// field is skipped when it is false. The list is fixed at compile time, a
// bounded, deterministic op list, and each stage is called directly (no
// function pointers), so that the static call graph, and the stack budget
// measured from it, sees every stage.
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

enum class StageId : uint8_t {
#define SPINHASH_STAGE_ID(id, Name, what) id,
  SPINHASH_STAGES(SPINHASH_STAGE_ID)
#undef SPINHASH_STAGE_ID
};

// Every stage's id in run order, and its name (the id, as `--set` spells it).
extern const StageId kStageOrder[];
extern const uint32_t kStageCount;
const char* stage_name(StageId id);

// false when `params` switch the stage off (its `enabled` field).
bool stage_enabled(StageId id, const StageParams& params);
// Runs one stage.
Status run_stage(StageId id, SearchContext& ctx);
// The stages that turn what the search found into the answer (carry: the
// first pass's poses on the full pass's features, at most kMaxCarriedPoses
// verifications; rank, confidence, classes): they still run once the work
// cap is reached, so a full pass capped before its draws answers with the
// first pass's leaders.
bool stage_answers(StageId id);
// Runs the enabled stages of ctx.params in order; the first status other
// than kOk ends the pass and is returned. Once the query's work reaches
// max_work (work_meter.hpp), only the stages that answer run, and the pass
// returns kWorkCapReached with the best answer found so far.
Status run_stages(SearchContext& ctx);

}  // namespace spinhash
