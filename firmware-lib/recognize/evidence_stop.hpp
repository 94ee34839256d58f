// BRAN's stop on evidence (evidence_stop.cpp): RANSAC's termination bound
// for doublets drawn from the joint candidates.
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

// Records `model`'s new best score for the stop on evidence (BRAN).
void note_leader(SearchContext& ctx, uint32_t model);
// true once more draws would most likely not change the leader
// (DrawsParams::stop_miss_probability, after min_evidence_draws).
bool evidence_says_stop(SearchContext& ctx);

}  // namespace spinhash
