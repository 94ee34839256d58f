// The coordinate reference system a point-cloud file declares, and what
// PROJ makes of it. LAS files declare it in an OGC or ESRI WKT record
// (LASF_Projection 2112) or in GeoTIFF GeoKeys (LASF_Projection 34735);
// cloud/las_crs.hpp reads which one the file means. The user may name one
// (`--work-crs EPSG:n`, a WKT or a PROJ string): cloud/crs_resolve.hpp.
// Files without one (PLY, text, most lab scans) have an unknown CRS and are
// processed in their own coordinates, taken as metres; outputs say so.
//
// Every front end (scene, recognize, survey, Python, the pictures) takes
// the units from here, compares CRSs by meaning (cloud/crs_match.hpp), and
// refuses degrees unless the user names a projected CRS to work in.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// GeoKey code for "user-defined" (GeoTIFF 6.0): not an EPSG code.
constexpr uint32_t kGeoKeyUserDefined = 32767;

// Metres per coordinate unit of a CRS's axes. The scene's size gates, the
// recognizer's radii and the database's models are in metres, while many
// surveys deliver in feet (US state plane systems in US survey feet, their
// heights too).
struct AxisUnits {
  double horizontal = 1.0;  // m per unit of x and y (1 for degrees: not scaled)
  double vertical = 1.0;    // m per unit of z
  std::string horizontal_name = "metre", vertical_name = "metre";
  // x, y are degrees (a geographic CRS): no linear scale; the tools refuse
  // such a file unless the user names a projected CRS to work in.
  bool geographic = false;
  std::vector<std::string> notes;  // what was assumed, and why

  bool metric() const { return horizontal == 1.0 && vertical == 1.0; }
  // "" for metres; else "x y in US survey foot (0.304800609601219 m), z in
  // ...: read as metres; ..." or why degrees cannot be.
  std::string describe() const;
  // The notes, then describe() unless empty: what a tool tells its user.
  std::vector<std::string> messages() const;
  // "US survey foot", or "metre; z in US survey foot" when they differ.
  std::string short_text() const;
};

struct Crs {
  // What the file (or the user) declares.
  std::string wkt;                    // OGC or ESRI WKT as the file holds it (empty: none)
  uint32_t horizontal_epsg = 0;       // GeoKeys' projected or geographic EPSG code (0: none)
  uint32_t vertical_epsg = 0;         // GeoKeys' vertical EPSG code (0: none)
  uint32_t linear_units_epsg = 0;     // GeoKeys' horizontal unit (9001 metre, 9002 foot, 9003 US foot)
  uint32_t vertical_units_epsg = 0;   // GeoKeys' vertical unit (0: none)
  std::string user;                   // what the user typed (--work-crs), when it comes from there
  std::string source;                 // "wkt", "geokeys", "user" or "" (unknown)
  std::vector<std::string> warnings;  // what was malformed, skipped or assumed

  // What PROJ makes of it (cloud/crs_resolve.hpp fills these).
  bool resolved = false;
  std::string definition;         // what PROJ reads: "EPSG:2903+5703", the WKT, or "" (unknown)
  std::string name;               // PROJ's name of the CRS ("NAD83(HARN) / New Mexico Central (ftUS)")
  uint32_t id_epsg = 0;           // the horizontal CRS's EPSG code, from its codes or its WKT's ID (0: none)
  uint32_t id_vertical_epsg = 0;  // the vertical CRS's, likewise
  AxisUnits units;

  // Declared (before resolution) or read by PROJ (after).
  bool known() const {
    return resolved ? !definition.empty() : !wkt.empty() || horizontal_epsg != 0 || !user.empty();
  }
  // "EPSG:26910", "EPSG:2903+5703", the CRS's name when it has no EPSG code
  // ("NAD_1983_HARN_Lambert_Conformal_Conic"), or "unknown".
  std::string describe() const;
  // What PROJ takes: the resolved definition, else the WKT or "EPSG:n";
  // "" when unknown.
  std::string proj_definition() const;
};

}  // namespace spinhash::host
