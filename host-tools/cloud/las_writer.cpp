#include "cloud/las_writer.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include "blob/file_io.hpp"
#include "cloud/las_reader.hpp"

namespace spinhash::host {
namespace {

constexpr uint8_t kWriteFormat = 1;          // x y z, intensity, flags, class, ..., GPS time
constexpr uint16_t kWriteRecordLength = 28;  // kLasMinRecordLength[1]
constexpr size_t kGpsTimeAt = 20;            // the record's GPS time (double)
constexpr uint8_t kUnclassified = 1;         // ASPRS class 1
constexpr uint8_t kLegacyClassMask = 0x1F;   // formats 0-5 hold 5 bits of class
constexpr uint8_t kSingleReturn = 0x09;      // return 1 of 1
constexpr size_t kPointCountAt = 107, kScaleAt = 131;

void put(std::string* b, size_t at, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i)
    (*b)[at + static_cast<size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFFu);
}
void put_double(std::string* b, size_t at, double d) {
  uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  put(b, at, bits, 8);
}

std::string header(uint64_t n, const double offset[3], const double lo[3], const double hi[3]) {
  std::string h(kLasHeaderBytes12, '\0');
  std::memcpy(&h[0], "LASF", 4);
  h[24] = 1;  // version 1.2
  h[25] = 2;
  std::memcpy(&h[26], "spinhash", 8);        // system identifier
  std::memcpy(&h[58], "spinhash scan", 13);  // generating software
  put(&h, 94, kLasHeaderBytes12, 2);         // header size
  put(&h, 96, kLasHeaderBytes12, 4);         // offset to point data: no VLRs
  h[104] = static_cast<char>(kWriteFormat);
  put(&h, 105, kWriteRecordLength, 2);
  put(&h, kPointCountAt, n, 4);
  put(&h, 111, n, 4);  // all first returns
  for (int a = 0; a < 3; ++a) {
    put_double(&h, kScaleAt + 8u * a, kLasWriteScale);
    put_double(&h, kScaleAt + 24u + 8u * a, offset[a]);
    put_double(&h, 179 + 16u * a, hi[a]);
    put_double(&h, 179 + 16u * a + 8u, lo[a]);
  }
  return h;
}

}  // namespace

bool las_bytes(const std::vector<double>& xyz, const std::vector<uint8_t>& classification, std::string* out,
               std::string* error) {
  return las_bytes(xyz, classification, {}, out, error);
}

bool las_bytes(const std::vector<double>& xyz, const std::vector<uint8_t>& classification,
               const std::vector<double>& gps_time, std::string* out, std::string* error) {
  const size_t n = xyz.size() / 3;
  if (!gps_time.empty() && gps_time.size() != n) {
    if (error)
      *error =
          "LAS writer: " + std::to_string(gps_time.size()) + " times for " + std::to_string(n) + " points";
    return false;
  }
  if (!classification.empty() && classification.size() != n) {
    if (error)
      *error = "LAS writer: " + std::to_string(classification.size()) + " classes for " + std::to_string(n) +
               " points";
    return false;
  }
  if (n > std::numeric_limits<uint32_t>::max()) {
    if (error) *error = "LAS writer: more points than LAS 1.2 can count";
    return false;
  }
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, offset[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    lo[a] = n ? std::numeric_limits<double>::infinity() : 0.0;
    hi[a] = n ? -std::numeric_limits<double>::infinity() : 0.0;
  }
  for (size_t i = 0; i < 3 * n; ++i) {
    if (!std::isfinite(xyz[i])) {
      if (error) *error = "LAS writer: point " + std::to_string(i / 3) + " is not finite";
      return false;
    }
    lo[i % 3] = std::min(lo[i % 3], xyz[i]);
    hi[i % 3] = std::max(hi[i % 3], xyz[i]);
  }
  for (int a = 0; a < 3; ++a) {
    offset[a] = std::floor(lo[a]);
    if ((hi[a] - offset[a]) / kLasWriteScale > std::numeric_limits<int32_t>::max()) {
      if (error) *error = "LAS writer: the cloud spans more than 32-bit integers hold at 1 mm";
      return false;
    }
  }
  *out = header(n, offset, lo, hi);
  std::string rec(kWriteRecordLength, '\0');
  out->reserve(out->size() + n * kWriteRecordLength);
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      const double q = std::round((xyz[3 * i + a] - offset[a]) / kLasWriteScale);
      put(&rec, 4u * a, static_cast<uint32_t>(static_cast<int32_t>(q)), 4);
    }
    rec[14] = static_cast<char>(kSingleReturn);
    rec[15] =
        static_cast<char>((classification.empty() ? kUnclassified : classification[i]) & kLegacyClassMask);
    put_double(&rec, kGpsTimeAt, gps_time.empty() ? 0.0 : gps_time[i]);
    out->append(rec);
  }
  return true;
}

bool write_las(const std::string& path, const std::vector<double>& xyz,
               const std::vector<uint8_t>& classification, std::string* error) {
  return write_las(path, xyz, classification, {}, error);
}

bool write_las(const std::string& path, const std::vector<double>& xyz,
               const std::vector<uint8_t>& classification, const std::vector<double>& gps_time,
               std::string* error) {
  std::string bytes;
  return las_bytes(xyz, classification, gps_time, &bytes, error) &&
         write_file_atomically(path, bytes.data(), bytes.size(), error);
}

}  // namespace spinhash::host
