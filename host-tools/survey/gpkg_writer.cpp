#include "survey/gpkg_writer.hpp"

#include <cpl_error.h>
#include <gdal.h>
#include <gdal_utils.h>

#include <cstdio>
#include <mutex>
#include <vector>

namespace spinhash::survey {
namespace {

// Tiles without a CRS: an engineering CRS in metres, so that no GIS takes
// the coordinates for longitudes and latitudes.
constexpr const char* kNativeWkt =
    "LOCAL_CS[\"spinhash native coordinates (no CRS)\",LOCAL_DATUM[\"unknown\",32767],"
    "UNIT[\"metre\",1],AXIS[\"x\",EAST],AXIS[\"y\",NORTH]]";

std::once_flag registered;

}  // namespace

bool write_geopackage(const std::string& geojson, const std::string& gpkg, const std::string& native_crs,
                      std::string* error) {
  std::call_once(registered, [] { GDALAllRegister(); });
  CPLErrorReset();
  const char* drivers[] = {"GeoJSON", nullptr};
  GDALDatasetH src =
      GDALOpenEx(geojson.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, nullptr, nullptr);
  if (src == nullptr) {
    *error = "GDAL cannot read " + geojson + ": " + CPLGetLastErrorMsg();
    return false;
  }
  // Without a CRS, the GeoJSON's coordinates are the tiles': assign the
  // engineering CRS; with one, bring WGS 84 back to the tiles' CRS.
  // GeoPackage columns hold no lists: the pose, centre and extent become JSON text.
  std::vector<std::string> args = {"-f",
                                   "GPKG",
                                   "-nln",
                                   "detections",
                                   "-overwrite",
                                   "-mapFieldType",
                                   "RealList=String,IntegerList=String,StringList=String"};
  if (native_crs.empty())
    args.insert(args.end(), {"-a_srs", kNativeWkt});
  else
    args.insert(args.end(), {"-t_srs", native_crs});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALVectorTranslateOptions* options = GDALVectorTranslateOptionsNew(argv.data(), nullptr);
  const std::string temp = gpkg + ".tmp.gpkg";
  std::remove(temp.c_str());
  int usage_error = 0;
  CPLPushErrorHandler(CPLQuietErrorHandler);  // messages come back through *error, not stderr
  GDALDatasetH out = GDALVectorTranslate(temp.c_str(), nullptr, 1, &src, options, &usage_error);
  CPLPopErrorHandler();
  GDALVectorTranslateOptionsFree(options);
  const bool ok = out != nullptr && usage_error == 0;
  if (!ok) *error = "GDAL cannot write " + gpkg + ": " + CPLGetLastErrorMsg();
  if (out != nullptr) GDALClose(out);
  GDALClose(src);
  if (ok && std::rename(temp.c_str(), gpkg.c_str()) != 0) {
    *error = "cannot rename " + temp + " to " + gpkg;
    return false;
  }
  if (!ok) std::remove(temp.c_str());
  return ok;
}

}  // namespace spinhash::survey
