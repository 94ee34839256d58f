#include "cloud/crs.hpp"

#include <cstdio>

namespace spinhash::host {
namespace {

// The WKT's own name: the first quoted string ("NAD83 / UTM zone 10N").
std::string wkt_name(const std::string& wkt) {
  const size_t a = wkt.find('"');
  if (a == std::string::npos) return wkt.substr(0, 40);
  const size_t b = wkt.find('"', a + 1);
  return wkt.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
}

std::string metres_text(double m) {
  char b[32];
  std::snprintf(b, sizeof b, "%.15g", m);
  return b;
}

}  // namespace

std::string AxisUnits::describe() const {
  if (geographic)
    return "x y in degrees (a geographic CRS): not metres, so no vehicle's size can be measured; reproject "
           "the file to a projected CRS, or name one to work in (--work-crs EPSG:n)";
  if (metric()) return "";
  std::string s = "x y in " + horizontal_name + " (" + metres_text(horizontal) + " m)";
  return s + ", z in " + vertical_name + " (" + metres_text(vertical) + " m): read as metres; sizes in m, " +
         "coordinates out in the CRS's units";
}

std::vector<std::string> AxisUnits::messages() const {
  std::vector<std::string> m = notes;
  const std::string units = describe();
  if (!units.empty()) m.push_back(units);
  return m;
}

std::string AxisUnits::short_text() const {
  if (geographic) return "degree";
  if (vertical_name == horizontal_name && vertical == horizontal) return horizontal_name;
  return horizontal_name + "; z in " + vertical_name;
}

std::string Crs::describe() const {
  if (!known()) return "unknown";
  if (id_epsg != 0) {
    std::string s = "EPSG:" + std::to_string(id_epsg);
    return id_vertical_epsg != 0 ? s + "+" + std::to_string(id_vertical_epsg) : s;
  }
  if (!name.empty()) return name;
  if (!wkt.empty()) return wkt_name(wkt);
  if (horizontal_epsg != 0) {
    std::string s = "EPSG:" + std::to_string(horizontal_epsg);
    return vertical_epsg != 0 ? s + "+" + std::to_string(vertical_epsg) : s;
  }
  return user;
}

std::string Crs::proj_definition() const {
  if (resolved) return definition;
  if (!wkt.empty()) return wkt;
  if (!user.empty()) return user;
  if (horizontal_epsg != 0) return "EPSG:" + std::to_string(horizontal_epsg);
  return "";
}

}  // namespace spinhash::host
