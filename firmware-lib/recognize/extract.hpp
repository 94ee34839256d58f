// The extract stage (stage_fields.h: ExtractParams): the object's points,
// loaded and rid of their ground, as oriented spin-image features
// (spinhash/features.hpp), quantised as the database's, and the search's
// view of them (ctx.query). The caller's measure of the terrain
// (ObjectTerrain), when given, stands for the ground stage's.
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

Status extract_stage(SearchContext& ctx);

}  // namespace spinhash
