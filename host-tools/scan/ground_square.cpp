#include "scan/ground_square.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/vehicle_generator.hpp"

namespace spinhash::host {

Mesh ground_square_around(const Mesh& object, double margin, double z) {
  const Box3 box = object.bounding_box();
  const double half =
      std::max({std::abs(box.lo.x()), std::abs(box.hi.x()), std::abs(box.lo.y()), std::abs(box.hi.y())}) +
      margin;
  return make_ground_patch(half, z);
}

}  // namespace spinhash::host
