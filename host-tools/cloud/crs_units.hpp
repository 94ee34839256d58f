// The units of a CRS's axes (AxisUnits, cloud/crs.hpp). The readers hand out
// a file's own coordinates; the reading door (cloud/metric_source.hpp)
// scales or reprojects them to metres, and the tools bring their
// georeferenced outputs back to the CRS's units on the way out.
#pragma once

#include "cloud/crs.hpp"

namespace spinhash::host {

// The units of crs's horizontal and vertical axes (PROJ's database): a
// compound CRS's parts, a vertical EPSG code, or the GeoKeys' unit codes
// when the projection itself is user-defined. Without a vertical CRS, z
// is taken in the horizontal unit (a note says so). An unknown CRS, or one
// PROJ cannot read, is taken as metres (a note says so). crs.units when
// crs is resolved (cloud/crs_resolve.hpp). Never throws.
AxisUnits axis_units(const Crs& crs);

}  // namespace spinhash::host
