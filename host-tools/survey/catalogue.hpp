// The survey's catalogue: every tile's header (bounds, point count, CRS),
// read without the points where the format allows (LAS/LAZ), sorted by path.
// A tile whose header cannot be read is refused, with the reason; the rest
// go on. Tiles must share a CRS; tiles without one are processed in their
// own coordinates (or, beside tiles that declare one, assumed to be in it),
// and the outputs say so.
#pragma once
#include <string>
#include <vector>

#include "cloud/point_source.hpp"

namespace spinhash::survey {

struct CatalogueTile {
  std::string path, name;  // name: the file's stem, the "tile" of every output
  host::CloudHeader header;
  bool bounds_from_points = false;  // the header had none (PLY, text): the points were read once
  std::string error;                // non-empty: refused, and why
};

struct Catalogue {
  std::vector<CatalogueTile> tiles;  // sorted by path
  host::Crs crs;                     // the survey's; unknown: native coordinates
  std::vector<std::string> notes;    // tiles assumed to be in the survey's CRS, ...
};

// The point-cloud files of the arguments: files as given, folders' files
// with a cloud extension (.las .laz .ply .txt .xyz .csv; not recursive).
// Sorted by path, duplicates removed. False with *error for a path that does
// not exist or a folder without clouds.
bool expand_tile_arguments(const std::vector<std::string>& args, std::vector<std::string>* paths,
                           std::string* error);

// Reads the headers (refusals recorded per tile, never thrown).
Catalogue read_catalogue(const std::vector<std::string>& sorted_paths);

// False with *error when two tiles declare different CRSs or share a name
// (their outputs would be confused); sets catalogue.crs and notes.
bool check_catalogue(Catalogue& catalogue, std::string* error);

}  // namespace spinhash::survey
