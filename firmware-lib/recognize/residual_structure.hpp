// The residual F (residual_structure.cpp; RankParams::residual_*): whether
// the first model's misfit is the scan's noise or a shape.
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

// F of the residuals' means per surface cell against their scatter within
// the cells, for `model` under `pose`: about 1 when the scan is the model
// plus noise, large when a patch of it sits off the model's surface (a
// vehicle outside the database); 0 when too few features fall in shared
// cells to tell.
float residual_structure(const SearchContext& ctx, uint32_t model, const RigidPose& pose);
// Within a look-alike group (group_size >= 2: the first models lie within
// the margin, which the likelihood cannot separate), the model whose
// residuals are the scan's noise comes first: swaps ranking[0] and
// ranking[1] when the second's residual F is the lower. Its score may then
// be the lower of the two.
void order_twins_by_residuals(const SearchContext& ctx, RankedModel* ranking, uint32_t group_size);

}  // namespace spinhash
