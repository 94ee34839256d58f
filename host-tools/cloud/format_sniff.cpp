#include "cloud/format_sniff.hpp"

#include <cstring>

namespace spinhash::host {

bool is_las(const std::string& bytes) { return bytes.rfind("LASF", 0) == 0; }

bool is_ply(const std::string& bytes) {
  return bytes.rfind("ply\n", 0) == 0 || bytes.rfind("ply\r\n", 0) == 0;
}

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

CloudFormat sniff_cloud_format(const std::string& head) {
  if (!foreign_cloud_format(head).empty()) return CloudFormat::kForeign;
  if (is_las(head)) return CloudFormat::kLas;
  if (is_ply(head)) return CloudFormat::kPly;
  return CloudFormat::kText;
}

}  // namespace spinhash::host
