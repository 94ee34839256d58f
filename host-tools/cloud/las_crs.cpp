#include "cloud/las_crs.hpp"

#include <string>

#include "cloud/crs_resolve.hpp"

namespace spinhash::host {
namespace {

constexpr size_t kKeyWords = 4;  // key id, TIFF tag location, count, value or offset
constexpr uint16_t kKeyDirectoryVersion = 1;

uint16_t word(const std::vector<uint8_t>& d, size_t i) {
  return static_cast<uint16_t>(d[2 * i] | (d[2 * i + 1] << 8));
}

// The key's value when stored inline (TIFF tag location 0), else 0.
void take_key(uint16_t id, uint16_t location, uint16_t value, Crs* crs, std::vector<uint16_t>* user_defined) {
  const bool units = id == kGeoKeyLinearUnits || id == kGeoKeyVerticalUnits;
  if (units && location == 0 && value != 0 && value != kGeoKeyUserDefined) {
    (id == kGeoKeyLinearUnits ? crs->linear_units_epsg : crs->vertical_units_epsg) = value;
    return;
  }
  const bool code = id == kGeoKeyProjectedCs || id == kGeoKeyGeographicCs || id == kGeoKeyVerticalCs;
  if (!code) return;
  if (location != 0) {
    crs->warnings.push_back("GeoKey " + std::to_string(id) + " is not stored inline; ignored");
    return;
  }
  if (value == kGeoKeyUserDefined || value == 0) {
    user_defined->push_back(id);  // said only when no WKT record describes the CRS instead
    return;
  }
  if (id == kGeoKeyVerticalCs)
    crs->vertical_epsg = value;
  else if (id == kGeoKeyProjectedCs || crs->horizontal_epsg == 0)
    crs->horizontal_epsg = value;  // projected wins
}

void read_geokeys(const Vlr& v, Crs* crs, std::vector<uint16_t>* user_defined) {
  const size_t words = v.data.size() / 2;
  if (words < kKeyWords || word(v.data, 0) != kKeyDirectoryVersion) {
    crs->warnings.push_back("GeoKeyDirectory is malformed (no version-1 header); ignored");
    return;
  }
  const size_t declared = word(v.data, 3);
  const size_t present = words / kKeyWords - 1;
  if (declared > present)
    crs->warnings.push_back("GeoKeyDirectory declares " + std::to_string(declared) + " keys, holds " +
                            std::to_string(present));
  size_t blank = 0;
  for (size_t k = 0; k < std::min(declared, present); ++k) {
    const size_t at = (k + 1) * kKeyWords;
    const uint16_t id = word(v.data, at);
    if (id == 0) {
      ++blank;
      continue;
    }
    take_key(id, word(v.data, at + 1), word(v.data, at + 3), crs, user_defined);
  }
  if (blank > 0)
    crs->warnings.push_back("GeoKeyDirectory has " + std::to_string(blank) + " blank (id 0) keys; skipped");
}

std::string wkt_text(const Vlr& v) {
  std::string s(v.data.begin(), v.data.end());
  const size_t nul = s.find('\0');
  return nul == std::string::npos ? s : s.substr(0, nul);
}

}  // namespace

Crs las_crs(const LasHeader& h, const std::vector<Vlr>& vlrs) {
  Crs crs;
  const Vlr* keys = find_vlr(vlrs, kLasProjectionUserId, kGeoKeyDirectoryRecord);
  const Vlr* wkt = find_vlr(vlrs, kLasProjectionUserId, kOgcWktRecord);
  const Vlr* liblas_wkt = find_vlr(vlrs, kLiblasUserId, kOgcWktRecord);
  std::vector<uint16_t> user_defined;  // keys whose value is 32767 (or 0)
  if (keys) read_geokeys(*keys, &crs, &user_defined);
  const bool wkt_bit = (h.global_encoding & kLasGlobalEncodingWkt) != 0;
  if (wkt && wkt_bit) {
    crs.wkt = wkt_text(*wkt);
  } else if (wkt_bit) {
    crs.warnings.push_back(
        "the global encoding's WKT bit is set but no WKT record (LASF_Projection 2112) found");
  } else if (crs.horizontal_epsg == 0 && (wkt || liblas_wkt)) {
    // GeoKeys that define the projection by its parameters (user-defined),
    // or none at all: the WKT record describes the same CRS in full.
    crs.wkt = wkt_text(wkt ? *wkt : *liblas_wkt);
    crs.warnings.push_back(std::string(keys ? "the GeoKeys name no EPSG code" : "no GeoKeys") +
                           ": the CRS is read from the " + (wkt ? "" : "liblas ") +
                           "WKT record (the global encoding's WKT bit is not set)");
  }
  if (crs.wkt.empty())
    for (uint16_t id : user_defined)
      crs.warnings.push_back("GeoKey " + std::to_string(id) +
                             " is user-defined: no EPSG code, and no WKT record");
  if (!crs.wkt.empty()) {
    crs.source = "wkt";  // the WKT says all; the GeoKeys stay as declared
  } else if (crs.horizontal_epsg != 0) {
    crs.source = "geokeys";
  }
  resolve_crs(&crs);
  return crs;
}

}  // namespace spinhash::host
