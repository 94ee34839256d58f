// Stop-gap: reads the whole file through read_cloud and hands it out in
// chunks. The chunked readers (LAS, LAZ, PLY, text) replace it.
#include "cloud/point_source.hpp"

#include <algorithm>
#include <vector>

#include "cloud/cloud_reader.hpp"

namespace spinhash::host {
namespace {

class WholeCloudSource final : public PointSource {
 public:
  WholeCloudSource(CloudHeader header, std::vector<double> xyz)
      : header_(std::move(header)), xyz_(std::move(xyz)) {}
  const CloudHeader& header() const override { return header_; }
  size_t read(double* xyz, size_t max_points) override {
    const size_t total = xyz_.size() / 3u;
    const size_t n = std::min(max_points, total - next_);
    std::copy(xyz_.begin() + 3 * next_, xyz_.begin() + 3 * (next_ + n), xyz);
    next_ += n;
    return n;
  }

 private:
  CloudHeader header_;
  std::vector<double> xyz_;
  size_t next_ = 0;
};

}  // namespace

std::unique_ptr<PointSource> open_point_source(const std::string& path) {
  std::vector<double> xyz;
  std::string error;
  if (!read_cloud(path, &xyz, &error)) throw CloudError(error);
  CloudHeader h;
  h.format = "unknown";
  h.count_known = true;
  h.point_count = xyz.size() / 3u;
  return std::make_unique<WholeCloudSource>(std::move(h), std::move(xyz));
}

CloudHeader read_cloud_header(const std::string& path) { return open_point_source(path)->header(); }

}  // namespace spinhash::host
