// The draws stage (sections 7-9; stage_fields.h: DrawsParams). BRAN:
// saliency-weighted doublet draws among the joint candidates, and for each
// draw every candidate pair of one model (the exhaustive W_k x W_l option)
// through the cascade, and when the candidates are spread over look-alikes
// also pairs of two look-alikes (not in the paper), until the evidence says
// the leader is found (evidence_stop.hpp) or the work budget is spent
// (max_trials draws, more while min_hypotheses is not met). SRAN: every
// model in turn, with its own candidates and sran_trials draws, through the
// same cascade, pose and likelihood.
#pragma once
#include <cstdint>

#include "recognize/search_context.hpp"

namespace spinhash {

Status draws_stage(SearchContext& ctx);

// BRAN's draws' budget: max_trials times the sparse scan's trial_scale, at
// most kMaxTrials (the extension's kTrialExtension times it stays within the
// draws' 32-bit count).
uint64_t trial_budget(const SearchContext& ctx);

}  // namespace spinhash
