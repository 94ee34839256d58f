// The CRS a LAS file declares: the OGC WKT record (LASF_Projection 2112)
// when the global encoding's WKT bit is set (LAS 1.4), else the GeoTIFF
// GeoKeyDirectory (LASF_Projection 34735): ProjectedCSTypeGeoKey (3072) or
// GeographicTypeGeoKey (2048) for the horizontal EPSG code,
// VerticalCSTypeGeoKey (4096) for the vertical one; ProjLinearUnitsGeoKey
// (3076) and VerticalUnitsGeoKey (4099) for the units (a user-defined
// projection in feet still says so). 32767 means user-defined: no EPSG
// code, a warning; then the WKT record (LASF_Projection 2112, or liblas's
// copy) describes the CRS when the file has one, as autzen's does. A
// malformed directory gives warnings and whatever its valid keys say, never
// an error. The CRS comes back resolved through PROJ (cloud/crs_resolve.hpp).
#pragma once

#include <vector>

#include "cloud/crs.hpp"
#include "cloud/las_header.hpp"
#include "cloud/las_vlrs.hpp"

namespace spinhash::host {

constexpr uint16_t kGeoKeyProjectedCs = 3072;
constexpr uint16_t kGeoKeyGeographicCs = 2048;
constexpr uint16_t kGeoKeyVerticalCs = 4096;
constexpr uint16_t kGeoKeyLinearUnits = 3076;
constexpr uint16_t kGeoKeyVerticalUnits = 4099;

Crs las_crs(const LasHeader& h, const std::vector<Vlr>& vlrs);

}  // namespace spinhash::host
