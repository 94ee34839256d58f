// The survey's catalogue: every tile's header (bounds, point count, CRS),
// read without the points where the format allows (LAS/LAZ), sorted by path.
// A tile whose header cannot be read is refused, with the reason; the rest
// go on. Tiles must share a CRS, compared by meaning (cloud/crs_match.hpp:
// an EPSG code and a WKT of the same CRS are one), unless the user names a
// CRS to work in, into which the others are reprojected. Tiles in degrees
// are refused unless so reprojected. Tiles without a CRS are processed in
// their own coordinates (or, beside tiles that declare one, assumed to be
// in it), and the outputs say so. Bounds are kept in metres of the CRS
// worked in (cloud/metric_source.hpp), as every tile is read.
#pragma once
#include <string>
#include <vector>

#include "cloud/metric_source.hpp"
#include "cloud/point_source.hpp"

namespace spinhash::survey {

struct CatalogueTile {
  std::string path, name;           // name: the file's stem, the "tile" of every output
  host::CloudHeader header;         // bounds in metres of the work CRS once checked
  bool bounds_from_points = false;  // the header had none (PLY, text): the points were read once
  std::string error;                // non-empty: refused, and why
};

struct Catalogue {
  std::vector<CatalogueTile> tiles;  // sorted by path
  host::Crs crs;                     // the survey's, resolved; unknown: native coordinates
  bool crs_named = false;            // the user named it: tiles in other CRSs are reprojected
  std::vector<std::string> notes;    // tiles assumed to be in the survey's CRS, ...
  host::WorkCrs work() const { return {crs, crs_named}; }
};

// The point-cloud files of the arguments: files as given, folders' files
// with a cloud extension (.las .laz .ply .txt .xyz .csv; not recursive).
// Sorted by path, duplicates removed. False with *error for a path that does
// not exist or a folder without clouds.
bool expand_tile_arguments(const std::vector<std::string>& args, std::vector<std::string>* paths,
                           std::string* error);

// Reads the headers (refusals recorded per tile, never thrown).
Catalogue read_catalogue(const std::vector<std::string>& sorted_paths);

// False with *error when two tiles declare different CRSs (naming both),
// a tile is in degrees without a named CRS to work in, or two tiles share a
// name (their outputs would be confused). Sets catalogue.crs (work: the
// user's, when named) and notes, and brings the bounds to metres (a tile
// whose bounds cannot be brought is refused).
bool check_catalogue(Catalogue& catalogue, const host::WorkCrs& work, std::string* error);

}  // namespace spinhash::survey
