// The rank stage (stage_fields.h: RankParams): every model that got a score,
// best first, with its pose in the input's coordinates; the look-alike group
// the margin cannot separate (confidence.hpp, lookalike_group_size); and
// within that group the model whose residuals are the scan's noise first
// (residual_structure.hpp, twins_by_residuals).
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

Status rank_stage(SearchContext& ctx);

}  // namespace spinhash
