// The recognizer's stages (stage_fields.h, SPINHASH_STAGES), run in order
// over one SearchContext: a pass. Each stage reads its parameters from the
// pass's config (ctx.params.<id>), counts in its block of the statistics
// (stats.<id>) and may stop the pass with a status (the ground and extract
// stages, on a cloud without enough features). A stage with an `enabled`
// field is skipped when it is false. The table is fixed at compile time:
// a bounded, deterministic list, as an op list of an inference engine.
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

enum class StageId : uint8_t {
#define SPINHASH_STAGE_ID(id, Name, what) id,
  SPINHASH_STAGES(SPINHASH_STAGE_ID)
#undef SPINHASH_STAGE_ID
};

struct Stage {
  StageId id;
  const char* name;                            // the id, as `--set` spells it
  Status (*run)(SearchContext& ctx);           // the stage's entry (its own header)
  bool (*enabled)(const StageParams& params);  // false: skipped
};

// Every stage, in run order.
extern const Stage kStages[];
extern const uint32_t kStageCount;

// Runs the enabled stages of ctx.params in order; the first status other
// than kOk ends the pass and is returned.
Status run_stages(SearchContext& ctx);

}  // namespace spinhash
