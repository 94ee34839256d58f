// The coordinate reference system a point-cloud file declares: LAS 1.4's
// OGC WKT record (LASF_Projection 2112, when the global encoding's WKT bit
// is set) or the GeoTIFF GeoKeyDirectory (LASF_Projection 34735). Files
// without either (PLY, text, most lab scans) have an unknown CRS and are
// processed in their own coordinates; outputs say so.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// GeoKey code for "user-defined" (GeoTIFF 6.0): not an EPSG code.
constexpr uint32_t kGeoKeyUserDefined = 32767;

struct Crs {
  std::string wkt;                 // OGC WKT as the file holds it (empty: none)
  uint32_t horizontal_epsg = 0;    // projected or geographic EPSG code (0: none)
  uint32_t vertical_epsg = 0;      // vertical EPSG code (0: none)
  uint32_t linear_units_epsg = 0;  // GeoKeys' horizontal unit (9001 metre, 9002 foot, 9003 US foot; 0: none)
  uint32_t vertical_units_epsg = 0;   // GeoKeys' vertical unit (0: none)
  std::string source;                 // "wkt", "geokeys" or "" (unknown)
  std::vector<std::string> warnings;  // what was malformed and skipped

  bool known() const { return !wkt.empty() || horizontal_epsg != 0; }
  // "EPSG:26910", "EPSG:32104+5703", "WKT: <name>" or "unknown".
  std::string describe() const;
  // What PROJ takes: "EPSG:n", the WKT, or "" when unknown.
  std::string proj_definition() const;
};

}  // namespace spinhash::host
