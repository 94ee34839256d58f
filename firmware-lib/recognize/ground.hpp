// The ground stage (not in the paper; stage_fields.h: GroundParams): an
// airborne scan of a vehicle holds the ground around it, which no model
// has; its flat spin images crowd the candidates and its points count as
// outliers in eq. 7. The terrain under the loaded points and a band above it
// are dropped (geometry/object_ground.hpp), and what the terrain says of the
// object (its top above it, its noise, the band) is kept for the class
// flag. A scene's terrain classifier does this for a whole tile instead
// (ObjectTerrain), with ground_clearance 0 here.
#pragma once
#include "recognize/search_context.hpp"

namespace spinhash {

Status ground_stage(SearchContext& ctx);

}  // namespace spinhash
