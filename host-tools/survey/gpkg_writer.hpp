// The GeoPackage for GIS users, through GDAL: the GeoJSON's features (so its
// columns are the same list of keys), with the geometry back in the tiles'
// CRS when it is known; in a local engineering CRS named "native coordinates
// (no CRS)" when it is not.
#pragma once
#include <string>

namespace spinhash::survey {

// Writes `gpkg` (replaced atomically: a temporary, then renamed) from the
// GeoJSON file. native_crs: the tiles' PROJ definition, "" when unknown.
bool write_geopackage(const std::string& geojson, const std::string& gpkg, const std::string& native_crs,
                      std::string* error);

}  // namespace spinhash::survey
