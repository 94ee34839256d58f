// Whether two declared CRSs are the same CRS, by meaning rather than by
// text: EPSG:2903, a WKT with AUTHORITY["EPSG","2903"] and another writer's
// WKT of NAD83(HARN) / New Mexico Central (ftUS) are one CRS. PROJ decides
// (proj_is_equivalent_to: same datum, projection, parameters and units),
// on the horizontal parts, a TOWGS84 binding set aside; vertical parts are
// compared when both declare one.
#pragma once

#include "cloud/crs.hpp"

namespace spinhash::host {

// Both must be known (resolved or not). Never throws.
bool same_crs(const Crs& a, const Crs& b);

}  // namespace spinhash::host
