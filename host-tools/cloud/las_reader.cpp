#include "cloud/las_reader.hpp"

#include <cmath>
#include <cstring>

namespace spinhash::host {
namespace {

// Little-endian fields at byte offsets of the public header (LAS 1.4, table 3).
constexpr size_t kVersionMajorAt = 24, kVersionMinorAt = 25, kHeaderSizeAt = 94, kPointOffsetAt = 96;
constexpr size_t kVlrCountAt = 100, kFormatAt = 104, kRecordLengthAt = 105, kLegacyCountAt = 107;
constexpr size_t kScaleAt = 131, kOffsetAt = 155, kBoundsAt = 179, kCount64At = 247;
constexpr uint8_t kCompressedFormatBits = 0xC0;         // LASzip sets bit 7 (and some writers bit 6)
constexpr uint8_t kLegacyClassMask = 0x1F;              // formats 0-5: 5 bits of class, 3 of flags
constexpr size_t kLegacyClassAt = 15, kClassAt14 = 16;  // byte of a point record holding the class
constexpr uint8_t kFirstFormat14 = 6;                   // formats 6-10: the 1.4 point layout

uint64_t le(const std::string& b, size_t at, int bytes) {
  uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<uint8_t>(b[at + static_cast<size_t>(i)]);
  return v;
}
double le_double(const std::string& b, size_t at) {
  const uint64_t bits = le(b, at, 8);
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}
int32_t le_int32(const std::string& b, size_t at) {
  const uint32_t u = static_cast<uint32_t>(le(b, at, 4));
  int32_t v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

bool fail(std::string* error, const std::string& why) {
  if (error) *error = "LAS: " + why;
  return false;
}

bool read_header(const std::string& b, LasHeader* h, std::string* error) {
  if (b.size() < kLasHeaderBytes12) return fail(error, "file shorter than the 227-byte header");
  h->version_major = static_cast<uint8_t>(b[kVersionMajorAt]);
  h->version_minor = static_cast<uint8_t>(b[kVersionMinorAt]);
  if (h->version_major != 1 || h->version_minor > 4)
    return fail(error, "version " + std::to_string(h->version_major) + "." +
                           std::to_string(h->version_minor) + " is not LAS 1.0-1.4");
  h->header_size = static_cast<uint16_t>(le(b, kHeaderSizeAt, 2));
  h->offset_to_points = static_cast<uint32_t>(le(b, kPointOffsetAt, 4));
  h->vlr_count = static_cast<uint32_t>(le(b, kVlrCountAt, 4));
  const uint8_t format_byte = static_cast<uint8_t>(b[kFormatAt]);
  h->record_length = static_cast<uint16_t>(le(b, kRecordLengthAt, 2));
  if (format_byte & kCompressedFormatBits)
    return fail(error,
                "compressed (LAZ) point data: decompress first, e.g. `laszip -i in.laz -o out.las` or "
                "`pdal translate in.laz out.las`");
  h->point_format = format_byte;
  const uint16_t needed = h->version_minor >= 4   ? kLasHeaderBytes14
                          : h->version_minor == 3 ? kLasHeaderBytes13
                                                  : kLasHeaderBytes12;
  if (h->header_size < needed || h->header_size > b.size())
    return fail(error, "header size " + std::to_string(h->header_size) + " does not fit LAS 1." +
                           std::to_string(h->version_minor) + " and a file of " + std::to_string(b.size()) +
                           " bytes");
  h->point_count = le(b, kLegacyCountAt, 4);
  if (h->version_minor >= 4) {
    const uint64_t count64 = le(b, kCount64At, 8);
    if (count64 != 0 || h->point_count == 0) h->point_count = count64;
  }
  for (int a = 0; a < 3; ++a) {
    h->scale[a] = le_double(b, kScaleAt + 8u * static_cast<size_t>(a));
    h->offset[a] = le_double(b, kOffsetAt + 8u * static_cast<size_t>(a));
    h->max[a] = le_double(b, kBoundsAt + 16u * static_cast<size_t>(a));
    h->min[a] = le_double(b, kBoundsAt + 16u * static_cast<size_t>(a) + 8u);
  }
  return true;
}

bool check_header(const std::string& b, const LasHeader& h, std::string* error) {
  if (h.point_format > kMaxLasPointFormat)
    return fail(error, "point data format " + std::to_string(h.point_format) + " is not one of 0-10");
  if (h.record_length < kLasMinRecordLength[h.point_format])
    return fail(error, "point record length " + std::to_string(h.record_length) + " is below format " +
                           std::to_string(h.point_format) + "'s " +
                           std::to_string(kLasMinRecordLength[h.point_format]));
  if (h.offset_to_points < h.header_size || h.offset_to_points > b.size())
    return fail(error, "offset to point data " + std::to_string(h.offset_to_points) +
                           " lies outside the file (header " + std::to_string(h.header_size) +
                           " bytes, file " + std::to_string(b.size()) + ")");
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(h.scale[a]) || h.scale[a] == 0.0 || !std::isfinite(h.offset[a]))
      return fail(error, "scale or offset of axis " + std::to_string(a) + " is zero or not finite");
  const uint64_t room = b.size() - h.offset_to_points;
  if (h.point_count > room / h.record_length)
    return fail(error, "truncated: the header declares " + std::to_string(h.point_count) + " points of " +
                           std::to_string(h.record_length) + " bytes, the file holds " +
                           std::to_string(room / h.record_length));
  return true;
}

}  // namespace

bool is_las(const std::string& bytes) { return bytes.rfind("LASF", 0) == 0; }

std::string foreign_cloud_format(const std::string& b) {
  auto starts = [&](const char* m, size_t n) { return b.size() >= n && std::memcmp(b.data(), m, n) == 0; };
  if (starts("\x1f\x8b", 2)) return "gzip-compressed data: decompress it first (gunzip FILE.gz)";
  if (starts("PK\x03\x04", 4)) return "a zip archive: unpack it first (unzip FILE.zip)";
  if (starts("ASTM-E57", 8))
    return "an E57 file: convert it to LAS or PLY first, e.g. `pdal translate in.e57 out.las`";
  if (starts("# .PCD", 6) || starts("VERSION .", 9) || starts("VERSION 0.", 10))
    return "a PCL PCD file: convert it to PLY or LAS first, e.g. `pcl_pcd2ply in.pcd out.ply` or "
           "`pdal translate in.pcd out.las`";
  return "";
}

bool parse_las(const std::string& b, LasCloud* out, std::string* error) {
  *out = LasCloud{};
  if (!is_las(b)) return fail(error, "no LASF signature");
  LasHeader h;
  if (!read_header(b, &h, error) || !check_header(b, h, error)) return false;
  const size_t n = static_cast<size_t>(h.point_count);
  out->xyz.resize(3 * n);
  out->classification.resize(n);
  const bool layout14 = h.point_format >= kFirstFormat14;
  for (size_t i = 0; i < n; ++i) {
    const size_t at = h.offset_to_points + i * h.record_length;
    for (int a = 0; a < 3; ++a)
      out->xyz[3 * i + static_cast<size_t>(a)] =
          static_cast<double>(le_int32(b, at + 4u * static_cast<size_t>(a))) * h.scale[a] + h.offset[a];
    const uint8_t c = static_cast<uint8_t>(b[at + (layout14 ? kClassAt14 : kLegacyClassAt)]);
    out->classification[i] = layout14 ? c : static_cast<uint8_t>(c & kLegacyClassMask);
  }
  out->header = h;
  return true;
}

}  // namespace spinhash::host
