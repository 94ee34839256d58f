// A declared CRS through PROJ (cloud/crs.hpp): what PROJ reads, its name,
// its EPSG codes (from the codes or the WKT's own ID; PROJ's search of its
// database by parameters takes seconds, so none is made), its units, and
// warnings for what PROJ does not know. Results are kept per definition, so
// a survey of tiles sharing a CRS asks PROJ once.
#pragma once

#include <string>

#include "cloud/crs.hpp"

namespace spinhash::host {

// Fills crs's resolved fields. A CRS PROJ cannot read becomes unknown (its
// GeoKeys' unit codes still give units), with a warning. Never throws.
void resolve_crs(Crs* crs);
Crs resolved(Crs crs);

// A CRS the user names: "EPSG:32610", "EPSG:2903+5703", a WKT or a PROJ
// string. False with *error when PROJ does not read it.
bool crs_from_user(const std::string& text, Crs* crs, std::string* error);

}  // namespace spinhash::host
