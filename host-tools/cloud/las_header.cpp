#include "cloud/las_header.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include "cloud/cloud_error.hpp"

namespace spinhash::host {
namespace {

// Little-endian fields at byte offsets of the public header (LAS 1.4, table 3).
constexpr size_t kGlobalEncodingAt = 6, kVersionMajorAt = 24, kVersionMinorAt = 25, kHeaderSizeAt = 94;
constexpr size_t kPointOffsetAt = 96, kVlrCountAt = 100, kFormatAt = 104, kRecordLengthAt = 105;
constexpr size_t kLegacyCountAt = 107, kLegacyByReturnAt = 111, kScaleAt = 131, kOffsetAt = 155;
constexpr size_t kBoundsAt = 179, kEvlrOffsetAt = 235, kEvlrCountAt = 243, kCount64At = 247;
constexpr size_t kByReturn64At = 255;
constexpr int kLegacyReturns = 5, kReturns14 = 15;
constexpr uint8_t kCompressedFormatBits = 0xC0;  // LASzip sets bit 7 (and some writers bit 6)
constexpr uint8_t kFormatBits = 0x3F;

uint64_t le(const uint8_t* b, size_t at, int bytes) {
  uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | b[at + static_cast<size_t>(i)];
  return v;
}
double le_double(const uint8_t* b, size_t at) {
  const uint64_t bits = le(b, at, 8);
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

[[noreturn]] void fail(const std::string& why) { throw CloudError("LAS: " + why); }

void read_fields(const uint8_t* b, LasHeader* h) {
  h->global_encoding = static_cast<uint16_t>(le(b, kGlobalEncodingAt, 2));
  h->offset_to_points = static_cast<uint32_t>(le(b, kPointOffsetAt, 4));
  h->vlr_count = static_cast<uint32_t>(le(b, kVlrCountAt, 4));
  const uint8_t format_byte = b[kFormatAt];
  h->compressed = (format_byte & kCompressedFormatBits) != 0;
  h->point_format = format_byte & kFormatBits;
  h->record_length = static_cast<uint16_t>(le(b, kRecordLengthAt, 2));
  h->point_count = le(b, kLegacyCountAt, 4);
  for (int r = 0; r < kLegacyReturns; ++r) h->points_by_return[r] = le(b, kLegacyByReturnAt + 4u * r, 4);
  for (int a = 0; a < 3; ++a) {
    h->scale[a] = le_double(b, kScaleAt + 8u * static_cast<size_t>(a));
    h->offset[a] = le_double(b, kOffsetAt + 8u * static_cast<size_t>(a));
    h->max[a] = le_double(b, kBoundsAt + 16u * static_cast<size_t>(a));
    h->min[a] = le_double(b, kBoundsAt + 16u * static_cast<size_t>(a) + 8u);
  }
}

// LAS 1.4: the 64-bit counts (when set) and the extended VLRs.
void read_fields14(const uint8_t* b, LasHeader* h) {
  h->evlr_offset = le(b, kEvlrOffsetAt, 8);
  h->evlr_count = static_cast<uint32_t>(le(b, kEvlrCountAt, 4));
  const uint64_t count64 = le(b, kCount64At, 8);
  if (count64 != 0 || h->point_count == 0) {
    h->point_count = count64;
    for (int r = 0; r < kReturns14; ++r) h->points_by_return[r] = le(b, kByReturn64At + 8u * r, 8);
  }
}

void check(const LasHeader& h, uint64_t file_size) {
  if (h.point_format > kMaxLasPointFormat)
    fail("point data format " + std::to_string(h.point_format) + " is not one of 0-10");
  // LAZ: the LASzip VLR says what a record holds (cloud/las_points.cpp checks
  // it before the record length, so a LAZ file without one is named as such).
  if (!h.compressed && h.record_length < kLasMinRecordLength[h.point_format])
    fail("point record length " + std::to_string(h.record_length) + " is below format " +
         std::to_string(h.point_format) + "'s " + std::to_string(kLasMinRecordLength[h.point_format]));
  if (h.offset_to_points < h.header_size || h.offset_to_points > file_size)
    fail("offset to point data " + std::to_string(h.offset_to_points) + " lies outside the file (header " +
         std::to_string(h.header_size) + " bytes, file " + std::to_string(file_size) + ")");
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(h.scale[a]) || h.scale[a] == 0.0 || !std::isfinite(h.offset[a]))
      fail("scale or offset of axis " + std::to_string(a) + " is zero or not finite");
  if (h.compressed) return;  // the LAZ decoder finds a truncated file
  const uint64_t room = file_size - h.offset_to_points;
  if (h.point_count > room / h.record_length)
    fail("truncated: the header declares " + std::to_string(h.point_count) + " points of " +
         std::to_string(h.record_length) + " bytes, the file holds " +
         std::to_string(room / h.record_length));
}

}  // namespace

LasHeader parse_las_header(const uint8_t* b, size_t n, uint64_t file_size) {
  if (n < 4 || std::memcmp(b, "LASF", 4) != 0) fail("no LASF signature");
  if (n < kLasHeaderBytes12 || file_size < kLasHeaderBytes12) fail("file shorter than the 227-byte header");
  LasHeader h;
  h.version_major = b[kVersionMajorAt];
  h.version_minor = b[kVersionMinorAt];
  if (h.version_major != 1 || h.version_minor > 4)
    fail("version " + std::to_string(h.version_major) + "." + std::to_string(h.version_minor) +
         " is not LAS 1.0-1.4");
  h.header_size = static_cast<uint16_t>(le(b, kHeaderSizeAt, 2));
  const uint16_t needed = h.version_minor >= 4   ? kLasHeaderBytes14
                          : h.version_minor == 3 ? kLasHeaderBytes13
                                                 : kLasHeaderBytes12;
  if (h.header_size < needed || h.header_size > file_size || h.header_size > n)
    fail("header size " + std::to_string(h.header_size) + " does not fit LAS 1." +
         std::to_string(h.version_minor) + " and a file of " + std::to_string(file_size) + " bytes");
  read_fields(b, &h);
  if (h.version_minor >= 4) read_fields14(b, &h);
  check(h, file_size);
  return h;
}

}  // namespace spinhash::host
