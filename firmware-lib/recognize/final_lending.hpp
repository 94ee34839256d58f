// The final lending (final_lending.cpp; BRAN; part of the refine stage).
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

// After the leaders are finalised, the first model's pose lent to its
// look-alikes, which are rescored, refined (when `refine`) and charged for
// their unseen surface alike (BRAN with the transfer stage on).
void lend_final_pose(SearchContext& ctx, const QueryFeatures& all, const LikelihoodParams& exact,
                     bool refine);

}  // namespace spinhash
