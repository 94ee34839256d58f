// LAS 1.0-1.4 point clouds (ASPRS), uncompressed, point data formats 0-10:
// what every airborne lidar system delivers. No Debian package reads LAS, so
// this is ours, hardened like the PLY reader: every header field is checked
// against the bytes present before any point is read, coordinates are scaled
// and offset in double (UTM northings need it), VLRs, EVLRs and extra bytes
// are skipped (the offset to the point data and the record length say where
// things are), and the classification is kept.
//
// Compressed and foreign formats are recognised by their first bytes and
// refused with a message that names them and says how to convert (LAZ, E57,
// PCD, gzip, zip).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

// The LAS point data format ids this reader takes, and the minimum record
// length of each (the standard's fields; a longer record carries extra bytes).
constexpr uint8_t kMaxLasPointFormat = 10;
constexpr uint16_t kLasMinRecordLength[kMaxLasPointFormat + 1] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
constexpr uint16_t kLasHeaderBytes12 = 227;  // LAS 1.0-1.2 public header
constexpr uint16_t kLasHeaderBytes13 = 235;  // 1.3 adds the waveform start
constexpr uint16_t kLasHeaderBytes14 = 375;  // 1.4 adds EVLRs and 64-bit counts
// Classification 2 is ground in every LAS version (ASPRS standard classes).
constexpr uint8_t kLasClassGround = 2;

struct LasHeader {
  uint8_t version_major = 0, version_minor = 0;
  uint8_t point_format = 0;
  uint16_t header_size = 0;
  uint16_t record_length = 0;
  uint32_t vlr_count = 0;  // as declared (the point-data offset decides where points start)
  uint32_t offset_to_points = 0;
  uint64_t point_count = 0;  // 1.4: the 64-bit count when set, else the legacy one
  double scale[3] = {0, 0, 0};
  double offset[3] = {0, 0, 0};
  double min[3] = {0, 0, 0}, max[3] = {0, 0, 0};  // bounds the header declares
};

struct LasCloud {
  LasHeader header;
  std::vector<double> xyz;              // scaled and offset, 3 per point
  std::vector<uint8_t> classification;  // one per point (formats 0-5: the low 5 bits)
};

// True when bytes begin with the LAS signature "LASF".
bool is_las(const std::string& bytes);

// Parses a whole LAS file held in memory. False with *error (and an empty
// cloud) for anything malformed, truncated or compressed; never throws.
bool parse_las(const std::string& bytes, LasCloud* out, std::string* error);

// A message naming a compressed or foreign point-cloud format recognised by
// its first bytes (LAZ is recognised by parse_las itself), with how to
// convert it; empty when none is recognised.
std::string foreign_cloud_format(const std::string& bytes);

}  // namespace spinhash::host
