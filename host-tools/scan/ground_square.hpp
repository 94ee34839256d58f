// The ground an airborne scan of a lone object also returns: a level square
// around the object, reaching `margin` beyond its footprint on every side.
#pragma once

#include "mesh/mesh.hpp"

namespace spinhash::host {

// At height z (a vehicle rests at its lowest z), centred on the object's
// origin: half the side the object's largest |x| or |y| plus margin.
Mesh ground_square_around(const Mesh& object, double margin, double z);

}  // namespace spinhash::host
