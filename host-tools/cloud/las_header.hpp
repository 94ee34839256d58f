// The LAS 1.0-1.4 public header: version, point format and record length,
// where the points start, how many there are, scale and offset, bounds, and
// (1.4) where the extended VLRs are. Every field is checked against the
// file's size before a point is read.
#pragma once

#include <cstddef>
#include <cstdint>

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
// Global encoding bit 4: the CRS is OGC WKT (LAS 1.4), not GeoTIFF keys.
constexpr uint16_t kLasGlobalEncodingWkt = 1u << 4;
// Formats 6-10 use the LAS 1.4 record layout.
constexpr uint8_t kLasFirstFormat14 = 6;

struct LasHeader {
  uint8_t version_major = 0, version_minor = 0;
  uint8_t point_format = 0;  // without the compression bits
  bool compressed = false;   // LAZ: bit 7 (or 6) of the format byte
  uint16_t global_encoding = 0;
  uint16_t header_size = 0;
  uint16_t record_length = 0;
  uint32_t vlr_count = 0;  // as declared (the point-data offset decides where points start)
  uint32_t offset_to_points = 0;
  uint64_t point_count = 0;            // 1.4: the 64-bit count when set, else the legacy one
  uint64_t points_by_return[15] = {};  // 1.0-1.3: the first 5 only
  double scale[3] = {0, 0, 0};
  double offset[3] = {0, 0, 0};
  double min[3] = {0, 0, 0}, max[3] = {0, 0, 0};  // bounds the header declares
  uint64_t evlr_offset = 0;                       // 1.4: the first extended VLR
  uint32_t evlr_count = 0;
};

// Parses and checks the header at the start of a file of file_size bytes;
// b holds its first n bytes (n >= the header size, or the whole file).
// Throws CloudError ("LAS: ...") naming what is wrong. An uncompressed file
// must hold every declared point; a LAZ file's points are checked by its
// decoder.
LasHeader parse_las_header(const uint8_t* b, size_t n, uint64_t file_size);

}  // namespace spinhash::host
