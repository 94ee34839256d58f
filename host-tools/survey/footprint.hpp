// A vehicle's footprint: the rectangle of its centre, length and width along
// its heading, as a closed ring counter-clockwise (RFC 7946's exterior
// rings), in the tiles' coordinates or in WGS 84 longitude/latitude (PROJ).
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "spinhash/scene.hpp"

namespace spinhash::survey {

using Ring = std::array<std::array<double, 2>, 5>;

// o's centre is in the tiles' units, its extent in metres: metres_per_unit
// (cloud/crs_units.hpp) brings the extent to the centre's units.
Ring footprint(const SceneObject& o, double metres_per_unit = 1.0);

// "[[x,y],...]" with enough digits for millimetres at 10^7 m.
std::string ring_json(const Ring& ring, int digits);

// The tiles' CRS to WGS 84 longitude/latitude (lon first, as RFC 7946 and
// GIS expect). One per thread: PROJ objects are not shared.
class ToWgs84 {
 public:
  // Throws std::runtime_error when PROJ does not know the definition.
  explicit ToWgs84(const std::string& proj_definition);
  ~ToWgs84();
  ToWgs84(const ToWgs84&) = delete;
  ToWgs84& operator=(const ToWgs84&) = delete;
  Ring transform(const Ring& native) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Digits of a WGS 84 coordinate: 12 significant, 1e-9 degree, 0.1 mm.
constexpr int kLonLatDigits = 12;
// Digits of a native coordinate: 15 significant, 0.1 mm at 10^7 m.
constexpr int kNativeDigits = 15;

}  // namespace spinhash::survey
