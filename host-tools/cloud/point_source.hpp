// Point clouds read in chunks of bounded size: the one door through which
// `scene`, `recognize`, the survey, Python and the experiments read files,
// so that memory never grows with the file (standard input is read whole
// first: it cannot be read twice). A header (bounds, count, format, CRS) can
// be read without any point: the survey's catalogue is built from headers.
// Every failure is a CloudError (cloud/cloud_error.hpp) naming the file.
// Whole-file reads are helpers on top (cloud/cloud_reader.hpp); the door in
// metres, with the CRS's units or a reprojection, is cloud/metric_source.hpp.
//
// Formats, told by their content (cloud/format_sniff.hpp): LAS 1.0-1.4, LAZ
// and COPC (our own decoder, cloud/laz/), PLY and x y z text. A file named
// .las, .laz or .ply whose content is not of that format is refused, as are
// compressed and foreign formats (with how to convert them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "blob/file_io.hpp"  // kStdinPath
#include "cloud/cloud_error.hpp"
#include "cloud/crs.hpp"
#include "cloud/point_filter.hpp"

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

class PointSource {
 public:
  virtual ~PointSource() = default;
  virtual const CloudHeader& header() const = 0;
  // Writes up to max_points points (x y z doubles, scaled and offset, NaN
  // passed through) to xyz[0 .. 3 * max_points) and returns how many; 0 at
  // the end of the cloud. Throws CloudError on malformed data, including a
  // file that ends before its declared count.
  virtual size_t read(double* xyz, size_t max_points) = 0;
  // Points read so far that the filter left out of what read() hands out
  // (cloud/point_filter.hpp: LAS and LAZ; noise, withheld, classes named).
  virtual uint64_t points_noise() const { return 0; }
};

// Largest cloud read whole into memory (standard input, bytes given).
constexpr uint64_t kMaxCloudFileBytes = 4ull << 30;

// The name of a cloud in JSON and messages: the file stem, or "stdin" for "-".
constexpr const char* kStdinName = "stdin";
std::string cloud_name(const std::string& path);

// Opens `path` ("-": standard input) and reads its header; filter: the
// points left out. Throws CloudError.
std::unique_ptr<PointSource> open_point_source(const std::string& path, const PointFilter& filter = {});
// The same over bytes in memory (fuzzing, embedded data); name in messages.
std::unique_ptr<PointSource> open_point_source_bytes(std::string bytes, const std::string& name,
                                                     const PointFilter& filter = {});

// The header alone (LAS/LAZ: without touching the points). Throws CloudError.
CloudHeader read_cloud_header(const std::string& path);

// Every point left in the source (x y z triples). Throws CloudError.
std::vector<double> read_all_points(PointSource& source);

}  // namespace spinhash::host
