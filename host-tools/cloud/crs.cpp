#include "cloud/crs.hpp"

namespace spinhash::host {
namespace {

// The WKT's own name: the first quoted string ("NAD83 / UTM zone 10N").
std::string wkt_name(const std::string& wkt) {
  const size_t a = wkt.find('"');
  if (a == std::string::npos) return wkt.substr(0, 40);
  const size_t b = wkt.find('"', a + 1);
  return wkt.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
}

}  // namespace

std::string Crs::describe() const {
  if (!wkt.empty()) return "WKT: " + wkt_name(wkt);
  if (horizontal_epsg == 0) return "unknown";
  std::string s = "EPSG:" + std::to_string(horizontal_epsg);
  if (vertical_epsg != 0) s += "+" + std::to_string(vertical_epsg);
  return s;
}

std::string Crs::proj_definition() const {
  if (!wkt.empty()) return wkt;
  if (horizontal_epsg != 0) return "EPSG:" + std::to_string(horizontal_epsg);
  return "";
}

}  // namespace spinhash::host
