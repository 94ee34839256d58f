// The focus stage (not in the paper; BRAN; stage_fields.h: FocusParams).
// When the joint candidates are spread over many look-alikes (each query
// feature's W candidates name a few dozen near-identical models), or so few
// poses were found that the draws were extended past max_trials
// (min_hypotheses), few doublets pair up in one model, and the true model
// may hold only a handful of poorer poses (or a look-alike's, lent by the
// pose transfer). The leading models after the draws are then nearly all of
// the right family, so each of the focus_models best gets the short RANSAC
// that SRAN gives every model: its own top_w_sran nearest features for an
// evenly spread share of the query features, and focus_trials draws through
// the same cascade and likelihood. Bounded: focus_models x (the searched
// features x one model's features) descriptor distances, and focus_trials x
// top_w_sran^2 pair checks per model, within max_pair_checks.
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

Status focus_stage(SearchContext& ctx);

}  // namespace spinhash
