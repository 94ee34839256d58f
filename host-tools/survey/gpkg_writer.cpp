#include "survey/gpkg_writer.hpp"

#include "survey/gdal_library.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace spinhash::survey {
namespace {

// Tiles without a CRS: an engineering CRS in metres, so that no GIS takes
// the coordinates for longitudes and latitudes.
constexpr const char* kNativeWkt =
    "LOCAL_CS[\"spinhash native coordinates (no CRS)\",LOCAL_DATUM[\"unknown\",32767],"
    "UNIT[\"metre\",1],AXIS[\"x\",EAST],AXIS[\"y\",NORTH]]";
constexpr const char* kLayer = "detections";
constexpr const char* kFootprint = "footprint";

size_t skip_space(const std::string& s, size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\n' || s[i] == '\r' || s[i] == '\t')) ++i;
  return i;
}

// The end (one past) of the JSON string starting at s[i] == '"'; npos if open.
size_t string_end(const std::string& s, size_t i) {
  for (++i; i < s.size(); ++i) {
    if (s[i] == '\\')
      ++i;
    else if (s[i] == '"')
      return i + 1;
  }
  return std::string::npos;
}

// The end (one past) of the JSON value at s[i].
size_t value_end(const std::string& s, size_t i) {
  if (i >= s.size()) return std::string::npos;
  if (s[i] == '"') return string_end(s, i);
  if (s[i] == '[' || s[i] == '{') {
    int depth = 0;
    for (; i < s.size(); ++i) {
      if (s[i] == '"') {
        i = string_end(s, i);
        if (i == std::string::npos) return i;
        --i;
      } else if (s[i] == '[' || s[i] == '{') {
        ++depth;
      } else if ((s[i] == ']' || s[i] == '}') && --depth == 0) {
        return i + 1;
      }
    }
    return std::string::npos;
  }
  while (i < s.size() && s[i] != ',' && s[i] != '}' && s[i] != ']') ++i;
  return i;
}

void put_utf8(uint32_t c, std::string* out) {
  if (c < 0x80) {
    out->push_back(static_cast<char>(c));
  } else if (c < 0x800) {
    out->push_back(static_cast<char>(0xC0 | (c >> 6)));
    out->push_back(static_cast<char>(0x80 | (c & 0x3F)));
  } else {
    out->push_back(static_cast<char>(0xE0 | (c >> 12)));
    out->push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (c & 0x3F)));
  }
}

// A JSON string's text (quotes and escapes removed).
std::string unquote(const std::string& raw) {
  std::string out;
  for (size_t i = 1; i + 1 < raw.size(); ++i) {
    if (raw[i] != '\\') {
      out.push_back(raw[i]);
      continue;
    }
    const char e = raw[++i];
    if (e == 'u' && i + 4 < raw.size()) {
      put_utf8(static_cast<uint32_t>(std::strtoul(raw.substr(i + 1, 4).c_str(), nullptr, 16)), &out);
      i += 4;
    } else {
      out.push_back(e == 'n'   ? '\n'
                    : e == 't' ? '\t'
                    : e == 'r' ? '\r'
                    : e == 'b' ? '\b'
                    : e == 'f' ? '\f'
                               : e);
    }
  }
  return out;
}

// The numbers of a ring "[[x,y],...]" (the footprint member: [ring]).
std::vector<double> ring_numbers(const std::string& raw) {
  std::vector<double> v;
  for (size_t i = 0; i < raw.size();) {
    const char c = raw[i];
    if (c == '-' || (c >= '0' && c <= '9')) {
      char* end = nullptr;
      v.push_back(std::strtod(raw.c_str() + i, &end));
      i = static_cast<size_t>(end - raw.c_str());
    } else {
      ++i;
    }
  }
  return v;
}

OGRFieldType field_type(ColumnType t) {
  switch (t) {
    case ColumnType::kInteger: return OFTInteger64;
    case ColumnType::kBoolean: return OFTInteger;  // with the Boolean subtype
    case ColumnType::kReal: return OFTReal;
    default: return OFTString;
  }
}

struct Closer {
  const GdalLibrary* g;
  void operator()(void* ds) const { g->GDALClose(static_cast<GDALDatasetH>(ds)); }
};

bool fail(const GdalLibrary& g, std::string* error, const std::string& what) {
  *error = what + (g.CPLGetLastErrorMsg()[0] != '\0' ? std::string(": ") + g.CPLGetLastErrorMsg() : "");
  return false;
}

bool set_field(const GdalLibrary& g, OGRFeatureH f, int index, ColumnType type, const std::string& raw) {
  if (raw == "null") {
    g.OGR_F_SetFieldNull(f, index);
    return true;
  }
  switch (type) {
    case ColumnType::kString: g.OGR_F_SetFieldString(f, index, unquote(raw).c_str()); break;
    case ColumnType::kJson: g.OGR_F_SetFieldString(f, index, raw.c_str()); break;  // our JSON, as written
    case ColumnType::kInteger:
      g.OGR_F_SetFieldInteger64(f, index, std::strtoll(raw.c_str(), nullptr, 10));
      break;
    case ColumnType::kBoolean: g.OGR_F_SetFieldInteger(f, index, raw == "true" ? 1 : 0); break;
    case ColumnType::kReal: g.OGR_F_SetFieldDouble(f, index, std::strtod(raw.c_str(), nullptr)); break;
  }
  return true;
}

bool add_feature(const GdalLibrary& g, OGRLayerH layer, const std::vector<Column>& columns,
                 const std::string& feature, std::string* error) {
  const size_t at = feature.rfind("\"properties\":");
  std::vector<std::pair<std::string, std::string>> members;
  if (at == std::string::npos ||
      !json_object_members(feature.substr(at + 13, feature.size() - at - 14), &members))
    return fail(g, error, "a detection that is not a GeoJSON feature");
  OGRFeatureH f = g.OGR_F_Create(g.OGR_L_GetLayerDefn(layer));
  for (const auto& m : members) {
    for (size_t c = 0; c < columns.size(); ++c)
      if (columns[c].name == m.first) set_field(g, f, static_cast<int>(c), columns[c].type, m.second);
    if (m.first != kFootprint) continue;
    const std::vector<double> xy = ring_numbers(m.second);
    OGRGeometryH ring = g.OGR_G_CreateGeometry(wkbLinearRing);
    for (size_t i = 0; i + 1 < xy.size(); i += 2) g.OGR_G_AddPoint_2D(ring, xy[i], xy[i + 1]);
    OGRGeometryH polygon = g.OGR_G_CreateGeometry(wkbPolygon);
    g.OGR_G_AddGeometryDirectly(polygon, ring);
    g.OGR_F_SetGeometryDirectly(f, polygon);
  }
  const bool ok = g.OGR_L_CreateFeature(layer, f) == OGRERR_NONE;
  g.OGR_F_Destroy(f);
  return ok || fail(g, error, "GDAL cannot add a detection");
}

bool write_layer(const GdalLibrary& g, GDALDatasetH ds, const std::vector<std::string>& features,
                 const std::vector<Column>& columns, const std::string& native_crs, std::string* error) {
  OGRSpatialReferenceH srs = g.OSRNewSpatialReference(nullptr);
  g.OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);  // x easting, y northing
  if (g.OSRSetFromUserInput(srs, native_crs.empty() ? kNativeWkt : native_crs.c_str()) != OGRERR_NONE) {
    g.OSRDestroySpatialReference(srs);
    return fail(g, error, "GDAL does not read the CRS " + native_crs.substr(0, 80));
  }
  OGRLayerH layer = g.GDALDatasetCreateLayer(ds, kLayer, srs, wkbPolygon, nullptr);
  g.OSRDestroySpatialReference(srs);
  if (layer == nullptr) return fail(g, error, "GDAL cannot make the layer");
  for (const Column& c : columns) {
    OGRFieldDefnH d = g.OGR_Fld_Create(c.name.c_str(), field_type(c.type));
    if (c.type == ColumnType::kBoolean) g.OGR_Fld_SetSubType(d, OFSTBoolean);
    if (c.type == ColumnType::kJson) g.OGR_Fld_SetSubType(d, OFSTJSON);
    const bool ok = g.OGR_L_CreateField(layer, d, TRUE) == OGRERR_NONE;
    g.OGR_Fld_Destroy(d);
    if (!ok) return fail(g, error, "GDAL cannot make the column " + c.name);
  }
  if (g.GDALDatasetStartTransaction(ds, FALSE) != OGRERR_NONE)
    return fail(g, error, "GDAL cannot start writing");
  for (const std::string& feature : features)
    if (!add_feature(g, layer, columns, feature, error)) return false;
  return g.GDALDatasetCommitTransaction(ds) == OGRERR_NONE ||
         fail(g, error, "GDAL cannot write the detections");
}

}  // namespace

bool json_object_members(const std::string& text, std::vector<std::pair<std::string, std::string>>* members) {
  members->clear();
  size_t i = skip_space(text, 0);
  if (i >= text.size() || text[i] != '{') return false;
  i = skip_space(text, i + 1);
  if (i < text.size() && text[i] == '}') return true;
  while (i < text.size()) {
    if (text[i] != '"') return false;
    const size_t key_end = string_end(text, i);
    if (key_end == std::string::npos) return false;
    const std::string key = unquote(text.substr(i, key_end - i));
    i = skip_space(text, key_end);
    if (i >= text.size() || text[i] != ':') return false;
    i = skip_space(text, i + 1);
    const size_t end = value_end(text, i);
    if (end == std::string::npos) return false;
    std::string raw = text.substr(i, end - i);
    while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\n')) raw.pop_back();
    members->emplace_back(key, raw);
    i = skip_space(text, end);
    if (i < text.size() && text[i] == '}') return true;
    if (i >= text.size() || text[i] != ',') return false;
    i = skip_space(text, i + 1);
  }
  return false;
}

bool write_geopackage(const std::vector<std::string>& features, const std::vector<Column>& columns,
                      const std::string& gpkg, const std::string& native_crs, std::string* error) {
  const GdalLibrary* library = gdal_library(error);
  if (library == nullptr) return false;
  const GdalLibrary& g = *library;
  g.CPLErrorReset();
  GDALDriverH driver = g.GDALGetDriverByName("GPKG");
  if (driver == nullptr) return fail(g, error, "GDAL has no GeoPackage driver");
  const std::string temp = gpkg + ".tmp.gpkg";
  std::remove(temp.c_str());
  bool ok = false;
  g.CPLPushErrorHandler(g.CPLQuietErrorHandler);  // messages come back through *error, not stderr
  {
    std::unique_ptr<void, Closer> ds(g.GDALCreate(driver, temp.c_str(), 0, 0, 0, GDT_Unknown, nullptr),
                                     Closer{&g});
    ok = ds ? write_layer(g, ds.get(), features, columns, native_crs, error)
            : fail(g, error, "GDAL cannot write " + gpkg);
  }
  g.CPLPopErrorHandler();
  if (ok && std::rename(temp.c_str(), gpkg.c_str()) != 0) {
    *error = "cannot rename " + temp + " to " + gpkg;
    ok = false;
  }
  if (!ok) std::remove(temp.c_str());
  return ok;
}

}  // namespace spinhash::survey
