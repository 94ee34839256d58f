// Point clouds read in chunks of bounded size: the one door through which
// `scene`, `recognize`, the survey and Python read files, so that memory
// never grows with the file. A header (bounds, count, format, CRS) can be
// read without any point: the survey's catalogue is built from headers.
//
// Formats: LAS 1.0-1.4, LAZ (our own decoder, cloud/laz/), PLY and text.
// Sniffing of compressed and foreign formats lives in one place
// (cloud/format_sniff.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "cloud/crs.hpp"

namespace spinhash::host {

// Points handed out per chunk by default: 64 Ki points, 1.5 MiB of doubles.
constexpr size_t kDefaultChunkPoints = size_t{1} << 16;

struct CloudHeader {
  std::string format;         // "las", "laz", "ply", "text"
  bool count_known = false;   // text: not until read
  uint64_t point_count = 0;   // as declared
  bool bounds_known = false;  // LAS/LAZ: the header's bounds
  double min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
  uint8_t las_point_format = 0;  // LAS/LAZ only
  uint8_t las_version[2] = {0, 0};
  Crs crs;
};

// Malformed or unreadable input, with a message naming the file and what is
// wrong. Everything already handed out stays valid.
class CloudError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PointSource {
 public:
  virtual ~PointSource() = default;
  virtual const CloudHeader& header() const = 0;
  // Writes up to max_points points (x y z doubles, scaled and offset, NaN
  // passed through) to xyz[0 .. 3 * max_points) and returns how many; 0 at
  // the end of the cloud. Throws CloudError on malformed data, including a
  // file that ends before its declared count.
  virtual size_t read(double* xyz, size_t max_points) = 0;
};

// Opens `path` ("-": standard input) and reads its header. Throws CloudError.
std::unique_ptr<PointSource> open_point_source(const std::string& path);

// The header alone (LAS/LAZ: without touching the points). Throws CloudError.
CloudHeader read_cloud_header(const std::string& path);

}  // namespace spinhash::host
