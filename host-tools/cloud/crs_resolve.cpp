#include "cloud/crs_resolve.hpp"

#include <proj_experimental.h>  // proj_crs_alter_cs_linear_unit, proj_create_compound_crs

#include <cmath>
#include <map>
#include <mutex>

#include "cloud/crs_proj.hpp"
#include "cloud/crs_units.hpp"

namespace spinhash::host {
namespace {

using crs_proj::Object;
using crs_proj::Parts;

struct Unit {
  bool found = false;
  double metres = 1.0;
  std::string name;
  bool angular = false;
};

// The unit of the first axis of a CRS's coordinate system.
Unit first_axis(const PJ* crs) {
  Unit u;
  if (crs == nullptr) return u;
  PJ_CONTEXT* ctx = crs_proj::context();
  const Object cs = crs_proj::make(proj_crs_get_coordinate_system(ctx, crs));
  const char* name = nullptr;
  double factor = 0.0;
  if (!cs ||
      !proj_cs_get_axis_info(ctx, cs.get(), 0, nullptr, nullptr, nullptr, &factor, &name, nullptr, nullptr))
    return u;
  u.found = factor > 0.0;
  u.metres = factor;
  u.name = name ? name : "";
  u.angular = proj_cs_get_type(ctx, cs.get()) == PJ_CS_TYPE_ELLIPSOIDAL;
  return u;
}

// A GeoKeys unit code (EPSG 9001, 9002, 9003...).
Unit unit_code(uint32_t code) {
  Unit u;
  const char* name = nullptr;
  const char* category = nullptr;
  double factor = 0.0;
  const std::string text = std::to_string(code);
  if (code == 0 ||
      !proj_uom_get_info_from_database(crs_proj::context(), "EPSG", text.c_str(), &name, &factor,
                                       &category) ||
      factor <= 0.0)
    return u;
  u.found = true;
  u.metres = factor;
  u.name = name ? name : text;
  u.angular = category != nullptr && std::string(category) == "angular";
  return u;
}

AxisUnits units_of(const Parts& parts, const Crs& crs, bool readable) {
  AxisUnits a;
  Unit h = first_axis(parts.horizontal.get());
  if (!h.found) h = unit_code(crs.linear_units_epsg);
  Unit v = first_axis(parts.vertical.get());
  if (!v.found) v = unit_code(crs.vertical_units_epsg);
  if (h.found && h.angular) {
    a.geographic = true;
    a.horizontal_name = h.name;
  } else if (h.found) {
    a.horizontal = h.metres;
    a.horizontal_name = h.name;
  }
  if (v.found && !v.angular) {
    a.vertical = v.metres;
    a.vertical_name = v.name;
  } else if (h.found && !h.angular) {
    a.vertical = h.metres;  // heights in the plane's unit: the usual delivery without a vertical CRS
    a.vertical_name = h.name;
    if (h.metres != 1.0) a.notes.push_back("no vertical CRS: z taken in " + h.name);
  }
  if (!h.found && readable) a.notes.push_back("no horizontal unit found: x y taken as metres");
  return a;
}

// The vertical GeoKey's code as PROJ takes it, or "" with a warning (files
// put a datum's code, 5103 for NAVD88, where the CRS's, 5703, belongs).
std::string vertical_part(Crs* crs) {
  if (crs->vertical_epsg == 0) return "";
  const std::string code = "EPSG:" + std::to_string(crs->vertical_epsg);
  const Object v = crs_proj::create(code);
  if (v && proj_get_type(v.get()) == PJ_TYPE_VERTICAL_CRS) return code;
  crs->warnings.push_back("VerticalCSTypeGeoKey " + std::to_string(crs->vertical_epsg) +
                          " is not a vertical CRS PROJ knows; ignored (z units from VerticalUnitsGeoKey)");
  return "";
}

std::string declared_definition(Crs* crs) {
  if (!crs->user.empty()) return crs->user;
  if (!crs->wkt.empty()) return crs->wkt;
  if (crs->horizontal_epsg == 0) return "";
  const std::string h = "EPSG:" + std::to_string(crs->horizontal_epsg);
  const std::string v = vertical_part(crs);
  return v.empty() ? h : h + "+" + v.substr(5);
}

// What resolution adds to a declaration, kept per declaration.
struct Resolution {
  std::string definition, name;
  uint32_t id_epsg = 0, id_vertical_epsg = 0;
  AxisUnits units;
  std::vector<std::string> warnings;
};

// GeoKeys whose ProjLinearUnitsGeoKey differs from their projected CRS's
// unit (EPSG:32128, in metres, with US survey feet): the key wins, as in
// libgeotiff and GDAL, and the CRS's axes are put in that unit (its
// projection parameters keep theirs, so the projection is unchanged).
// False when the units agree or the CRS is not from GeoKeys.
bool override_linear_unit(const Crs& crs, Parts* parts, std::string* warning) {
  if (crs.source != "geokeys" || !parts->horizontal) return false;
  const Unit key = unit_code(crs.linear_units_epsg), axis = first_axis(parts->horizontal.get());
  if (!key.found || key.angular || !axis.found || axis.angular) return false;
  if (std::abs(key.metres - axis.metres) <= 1e-12 * axis.metres) return false;
  const std::string code = std::to_string(crs.linear_units_epsg);
  Object altered = crs_proj::make(proj_crs_alter_cs_linear_unit(
      crs_proj::context(), parts->horizontal.get(), key.name.c_str(), key.metres, "EPSG", code.c_str()));
  if (!altered) return false;
  *warning = "ProjLinearUnitsGeoKey says " + key.name + " where EPSG:" + std::to_string(crs.horizontal_epsg) +
             " is in " + axis.name + ": x y read in " + key.name + " (as libgeotiff and GDAL do)";
  parts->horizontal = std::move(altered);
  return true;
}

// The WKT of the parts (a compound CRS when both are there).
std::string parts_wkt(const Parts& parts) {
  PJ_CONTEXT* ctx = crs_proj::context();
  Object whole = crs_proj::none();
  if (parts.vertical)
    whole = crs_proj::make(proj_create_compound_crs(ctx, proj_get_name(parts.horizontal.get()),
                                                    parts.horizontal.get(), parts.vertical.get()));
  const char* wkt = proj_as_wkt(ctx, whole ? whole.get() : parts.horizontal.get(), PJ_WKT2_2019, nullptr);
  return wkt != nullptr ? wkt : "";
}

Resolution resolve_uncached(Crs crs) {
  Resolution r;
  const size_t warned = crs.warnings.size();
  const std::string definition = declared_definition(&crs);
  Object whole = crs_proj::create(definition);
  const bool readable = static_cast<bool>(whole);
  if (!definition.empty() && !readable)
    crs.warnings.push_back("PROJ does not read the CRS (" + crs.describe() + ": " + crs_proj::last_error() +
                           "): processed in the file's own coordinates");
  if (readable) {
    r.definition = definition;
    r.name = proj_get_name(whole.get()) ? proj_get_name(whole.get()) : "";
  }
  Parts parts = crs_proj::split(std::move(whole));
  r.id_epsg = crs_proj::epsg_id(parts.horizontal.get());
  r.id_vertical_epsg = crs_proj::epsg_id(parts.vertical.get());
  std::string warning;
  if (override_linear_unit(crs, &parts, &warning)) {
    crs.warnings.push_back(warning);
    r.definition = parts_wkt(parts);
    r.name += " in " + first_axis(parts.horizontal.get()).name;
    r.id_epsg = 0;  // no longer the registered CRS
  }
  r.units = units_of(parts, crs, readable);
  r.warnings.assign(crs.warnings.begin() + static_cast<long>(warned), crs.warnings.end());
  return r;
}

std::string cache_key(const Crs& c) {
  return c.user + '\x1f' + c.wkt + '\x1f' + std::to_string(c.horizontal_epsg) + ',' +
         std::to_string(c.vertical_epsg) + ',' + std::to_string(c.linear_units_epsg) + ',' +
         std::to_string(c.vertical_units_epsg);
}

constexpr size_t kMaxCached = 256;  // distinct CRSs a process keeps; a survey has one or a few

}  // namespace

void resolve_crs(Crs* crs) {
  static std::mutex mutex;
  static std::map<std::string, Resolution> cache;
  const std::string key = cache_key(*crs);
  Resolution r;
  bool hit = false;
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find(key);
    if (it != cache.end()) r = it->second, hit = true;
  }
  if (!hit) {
    r = resolve_uncached(*crs);
    std::lock_guard<std::mutex> lock(mutex);
    if (cache.size() >= kMaxCached) cache.clear();
    cache.emplace(key, r);
  }
  crs->resolved = true;
  crs->definition = r.definition;
  crs->name = r.name;
  crs->id_epsg = r.id_epsg;
  crs->id_vertical_epsg = r.id_vertical_epsg;
  crs->units = r.units;
  crs->warnings.insert(crs->warnings.end(), r.warnings.begin(), r.warnings.end());
  if (crs->definition.empty()) crs->source.clear();
}

Crs resolved(Crs crs) {
  if (!crs.resolved) resolve_crs(&crs);
  return crs;
}

AxisUnits axis_units(const Crs& crs) { return crs.resolved ? crs.units : resolved(crs).units; }

bool crs_from_user(const std::string& text, Crs* crs, std::string* error) {
  Crs c;
  c.user = text;
  c.source = "user";
  resolve_crs(&c);
  if (!c.known()) {
    *error = "PROJ does not read the CRS \"" + text.substr(0, 80) +
             "\": give an EPSG code (EPSG:32610), a WKT "
             "or a PROJ string";
    return false;
  }
  *crs = std::move(c);
  return true;
}

}  // namespace spinhash::host
