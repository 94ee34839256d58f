// Metres per coordinate unit of a file's CRS. The scene's size gates, the
// recognizer's radii and the database's models are in metres, while many
// surveys deliver in feet (US state plane systems in US survey feet, their
// heights too). The readers hand out the file's own coordinates; the tools
// scale them to metres on the way in (cloud/metric_source.hpp) and their
// georeferenced outputs back to the file's units on the way out.
#pragma once

#include <string>
#include <vector>

#include "cloud/crs.hpp"

namespace spinhash::host {

struct AxisUnits {
  double horizontal = 1.0;  // m per unit of x and y (1 for degrees: not scaled)
  double vertical = 1.0;    // m per unit of z
  std::string horizontal_name = "metre", vertical_name = "metre";
  // x, y are degrees (a geographic CRS): no linear scale, so horizontal
  // stays 1; the tools process them as they are and say so.
  bool geographic = false;
  std::vector<std::string> notes;  // what was assumed, and why

  bool metric() const { return horizontal == 1.0 && vertical == 1.0; }
  // "" for metres; else "x y in US survey foot (0.304800609601219 m), z in
  // ...: read as metres; ..." or why degrees cannot be.
  std::string describe() const;
  // The notes, then describe() unless empty: what a tool tells its user.
  std::vector<std::string> messages() const;
};

// The units of crs's horizontal and vertical axes (PROJ's database): a
// compound CRS's parts, a vertical EPSG code, or the GeoKeys' unit codes
// when the projection itself is user-defined. Without a vertical CRS, z
// is taken in the horizontal unit (a note says so). An unknown CRS, or one
// PROJ cannot read, is taken as metres (a note says so). Never throws.
AxisUnits axis_units(const Crs& crs);

}  // namespace spinhash::host
