// GDAL, loaded when the first GeoPackage is written rather than when a
// command starts: libgdal pulls in about a hundred shared libraries, and
// linking them costs every command (a sparse tile's whole `scene` run)
// more start-up time than its work. The functions the GeoPackage writer
// calls are listed once below; the loader resolves each by name from the
// library the build found (SPINHASH_GDAL_SONAME).
#pragma once
#include <cpl_error.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <string>

// clang-format off
#define SPINHASH_GDAL_FUNCTIONS(F) \
  F(CPLErrorReset) \
  F(CPLGetLastErrorMsg) \
  F(CPLPushErrorHandler) \
  F(CPLPopErrorHandler) \
  F(CPLQuietErrorHandler) \
  F(GDALAllRegister) \
  F(GDALGetDriverByName) \
  F(GDALCreate) \
  F(GDALClose) \
  F(GDALDatasetCreateLayer) \
  F(GDALDatasetStartTransaction) \
  F(GDALDatasetCommitTransaction) \
  F(OSRNewSpatialReference) \
  F(OSRDestroySpatialReference) \
  F(OSRSetAxisMappingStrategy) \
  F(OSRSetFromUserInput) \
  F(OGR_L_CreateField) \
  F(OGR_L_CreateFeature) \
  F(OGR_L_GetLayerDefn) \
  F(OGR_Fld_Create) \
  F(OGR_Fld_Destroy) \
  F(OGR_Fld_SetSubType) \
  F(OGR_F_Create) \
  F(OGR_F_Destroy) \
  F(OGR_F_SetFieldNull) \
  F(OGR_F_SetFieldString) \
  F(OGR_F_SetFieldInteger) \
  F(OGR_F_SetFieldInteger64) \
  F(OGR_F_SetFieldDouble) \
  F(OGR_F_SetGeometryDirectly) \
  F(OGR_G_CreateGeometry) \
  F(OGR_G_AddPoint_2D) \
  F(OGR_G_AddGeometryDirectly)
// clang-format on

namespace spinhash::survey {

// GDAL's functions, by their own names and types.
struct GdalLibrary {
#define SPINHASH_GDAL_POINTER(name) decltype(&::name) name = nullptr;
  SPINHASH_GDAL_FUNCTIONS(SPINHASH_GDAL_POINTER)
#undef SPINHASH_GDAL_POINTER
};

// The library, loaded and its drivers registered on the first call (any
// thread); nullptr with *error when it cannot be loaded or lacks a function.
const GdalLibrary* gdal_library(std::string* error);

}  // namespace spinhash::survey
