// The candidates stage (section 5; stage_fields.h: CandidatesParams). First,
// for every mode, the query's footprint density decides whether it is
// searched as a sparse scan (sparse_search.hpp). BRAN: each query feature's
// top_w nearest model features from the joint LSH index, their saliency
// weights for the draws (section 6), and whether they spread over many
// look-alikes. SIND: each feature's top_w_sind nearest features vote for
// their models. SRAN gathers each model's own candidates in the draws stage.
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

Status candidates_stage(SearchContext& ctx);

}  // namespace spinhash
