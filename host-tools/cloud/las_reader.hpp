// LAS 1.0-1.4 point clouds (ASPRS), point data formats 0-10, uncompressed or
// LASzip-compressed (LAZ, COPC; our own decoder in cloud/laz/): what every
// airborne lidar system delivers. Split as PDAL splits its reader: the
// header (cloud/las_header.hpp), the VLRs and CRS (cloud/las_vlrs.hpp,
// cloud/las_crs.hpp), the point records (cloud/las_points.hpp) and format
// sniffing (cloud/format_sniff.hpp). Every header field is checked against
// the bytes present before any point is read, coordinates are scaled and
// offset in double (UTM northings need it), extra bytes are skipped (the
// record length says where the next point is), and the classification is
// kept.
//
// This file reads a whole file held in memory; cloud/point_source.hpp reads
// files in chunks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cloud/crs.hpp"
#include "cloud/format_sniff.hpp"
#include "cloud/las_header.hpp"

namespace spinhash::host {

struct LasCloud {
  LasHeader header;
  Crs crs;
  std::vector<double> xyz;              // scaled and offset, 3 per point
  std::vector<uint8_t> classification;  // one per point (formats 0-5: the low 5 bits)
};

// Parses a whole LAS or LAZ file held in memory. False with *error (and an
// empty cloud) for anything malformed, truncated or undecodable; never throws.
bool parse_las(const std::string& bytes, LasCloud* out, std::string* error);

}  // namespace spinhash::host
