// The carry stage (stage_fields.h: CarryParams): the cascade's full pass
// starts from what its first pass found. The first pass's leading poses
// (up to carry_models, kept in the workspace by recognizer.cpp) are verified
// on this pass's features before any doublet is drawn, so an escalated
// query keeps its first answer's poses and the draws search past them.
// Does nothing on a first pass or a single pass (nothing carried) and in
// SIND (no poses). Bounded: kMaxCarriedPoses verifications.
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

Status carry_stage(SearchContext& ctx);

// Keeps the leading poses of the pass that just ended (its ranking) for the
// next pass's carry stage.
void keep_leading_poses(SearchContext& ctx);

}  // namespace spinhash
