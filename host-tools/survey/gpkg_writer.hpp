// The GeoPackage for GIS users, through GDAL's OGR API: layer "detections",
// one polygon per vehicle candidate (its footprint, in the tiles' CRS, or
// in a local engineering CRS named "native coordinates (no CRS)" when they
// declare none), and one typed column per member of the detections' JSON
// lines (survey/tile_result.hpp's columns): text, integers, reals, booleans,
// and JSON (String with GDAL's JSON subtype) for the arrays and objects
// (pose, centre, extent, ranking), written as the JSON lines write them.
// The schema is there even when the survey found nothing.
#pragma once
#include <string>
#include <vector>

#include "survey/tile_result.hpp"

namespace spinhash::survey {

// Writes `gpkg` (replaced atomically: a temporary, then renamed) from the
// GeoJSON features' properties (a "footprint" member: the ring in the
// tiles' coordinates). native_crs: the tiles' PROJ definition, "" when
// unknown. False with *error.
bool write_geopackage(const std::vector<std::string>& features, const std::vector<Column>& columns,
                      const std::string& gpkg, const std::string& native_crs, std::string* error);

// The members of a flat JSON object, each value as its raw JSON text; false
// when the text is not one JSON object.
bool json_object_members(const std::string& text, std::vector<std::pair<std::string, std::string>>* members);

}  // namespace spinhash::survey
