#include "cloud/crs_units.hpp"

#include <proj.h>

#include <cstdio>
#include <memory>

namespace spinhash::host {
namespace {

using Context = std::unique_ptr<PJ_CONTEXT, decltype(&proj_context_destroy)>;
using Object = std::unique_ptr<PJ, decltype(&proj_destroy)>;

Object none() { return Object(nullptr, proj_destroy); }

struct Unit {
  bool found = false;
  double metres = 1.0;
  std::string name;
  bool angular = false;
};

// A bound CRS (a WKT with TOWGS84) stands for its source CRS.
Object unbound(PJ_CONTEXT* ctx, Object crs) {
  if (crs && proj_get_type(crs.get()) == PJ_TYPE_BOUND_CRS)
    return Object(proj_get_source_crs(ctx, crs.get()), proj_destroy);
  return crs;
}

// The unit of the first axis of a CRS's coordinate system.
Unit first_axis(PJ_CONTEXT* ctx, const PJ* crs) {
  Unit u;
  if (crs == nullptr) return u;
  const Object cs(proj_crs_get_coordinate_system(ctx, crs), proj_destroy);
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
Unit unit_code(PJ_CONTEXT* ctx, uint32_t code) {
  Unit u;
  const char* name = nullptr;
  const char* category = nullptr;
  double factor = 0.0;
  const std::string text = std::to_string(code);
  if (code == 0 || !proj_uom_get_info_from_database(ctx, "EPSG", text.c_str(), &name, &factor, &category) ||
      factor <= 0.0)
    return u;
  u.found = true;
  u.metres = factor;
  u.name = name ? name : text;
  u.angular = category != nullptr && std::string(category) == "angular";
  return u;
}

struct Parts {
  Object horizontal = none(), vertical = none();
};

Parts crs_parts(PJ_CONTEXT* ctx, const Crs& crs, std::vector<std::string>* notes) {
  Parts p;
  const std::string definition = crs.proj_definition();
  if (!definition.empty()) {
    Object whole = unbound(ctx, Object(proj_create(ctx, definition.c_str()), proj_destroy));
    if (!whole) {
      notes->push_back("PROJ does not read the CRS (" + crs.describe() + ")");
    } else if (proj_get_type(whole.get()) == PJ_TYPE_COMPOUND_CRS) {
      p.horizontal = unbound(ctx, Object(proj_crs_get_sub_crs(ctx, whole.get(), 0), proj_destroy));
      p.vertical = unbound(ctx, Object(proj_crs_get_sub_crs(ctx, whole.get(), 1), proj_destroy));
    } else if (proj_get_type(whole.get()) == PJ_TYPE_VERTICAL_CRS) {
      p.vertical = std::move(whole);
    } else {
      p.horizontal = std::move(whole);
    }
  }
  if (!p.vertical && crs.vertical_epsg != 0) {
    const std::string code = "EPSG:" + std::to_string(crs.vertical_epsg);
    p.vertical = Object(proj_create(ctx, code.c_str()), proj_destroy);
    if (!p.vertical) notes->push_back("PROJ does not know the vertical CRS " + code);
  }
  return p;
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
           "the "
           "file to a projected CRS";
  if (metric()) return "";
  std::string s = "x y in " + horizontal_name + " (" + metres_text(horizontal) + " m)";
  return s + ", z in " + vertical_name + " (" + metres_text(vertical) + " m): read as metres; sizes in m, " +
         "coordinates out in the file's units";
}

std::vector<std::string> AxisUnits::messages() const {
  std::vector<std::string> m = notes;
  const std::string units = describe();
  if (!units.empty()) m.push_back(units);
  return m;
}

AxisUnits axis_units(const Crs& crs) {
  AxisUnits a;
  if (!crs.known() && crs.linear_units_epsg == 0 && crs.vertical_units_epsg == 0) return a;
  const Context ctx(proj_context_create(), proj_context_destroy);
  if (!ctx) return a;
  proj_log_level(ctx.get(), PJ_LOG_NONE);
  const Parts parts = crs_parts(ctx.get(), crs, &a.notes);
  Unit h = first_axis(ctx.get(), parts.horizontal.get());
  if (!h.found) h = unit_code(ctx.get(), crs.linear_units_epsg);
  Unit v = first_axis(ctx.get(), parts.vertical.get());
  if (!v.found) v = unit_code(ctx.get(), crs.vertical_units_epsg);
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
  if (!h.found && crs.known()) a.notes.push_back("no horizontal unit found: x y taken as metres");
  return a;
}

}  // namespace spinhash::host
