// LAS and LAZ are read in chunks through LasRecordReader (a LAZ chunk is
// decoded at a time); PLY and text still go through read_cloud whole (a
// stop-gap until their chunked readers land).
#include "cloud/point_source.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud/format_sniff.hpp"
#include "cloud/las_points.hpp"

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

CloudHeader las_cloud_header(const LasRecordReader& r) {
  const LasHeader& h = r.header();
  CloudHeader c;
  c.format = h.compressed ? "laz" : "las";
  c.count_known = true;
  c.point_count = h.point_count;
  c.bounds_known = true;
  for (int a = 0; a < 3; ++a) {
    c.min[a] = h.min[a];
    c.max[a] = h.max[a];
  }
  c.las_point_format = h.point_format;
  c.las_version[0] = h.version_major;
  c.las_version[1] = h.version_minor;
  c.crs = r.crs();
  return c;
}

class LasSource final : public PointSource {
 public:
  LasSource(std::string name, std::unique_ptr<std::string> owned, std::unique_ptr<ByteSource> src)
      : name_(std::move(name)), owned_(std::move(owned)), reader_(named(std::move(src))) {
    header_ = las_cloud_header(*reader_);
    batch_ = las_batch_records(reader_->header());
    records_.resize(batch_ * reader_->header().record_length);
  }
  const CloudHeader& header() const override { return header_; }
  size_t read(double* xyz, size_t max_points) override {
    size_t done = 0;
    while (done < max_points) {
      if (next_ == held_) refill();
      if (held_ == 0) break;
      const size_t n = std::min(max_points - done, held_ - next_);
      const uint16_t length = reader_->header().record_length;
      for (size_t i = 0; i < n; ++i)
        las_record_xyz(reader_->header(), records_.data() + (next_ + i) * length, xyz + 3 * (done + i));
      next_ += n;
      done += n;
    }
    return done;
  }

 private:
  std::unique_ptr<LasRecordReader> named(std::unique_ptr<ByteSource> src) {
    try {
      return std::make_unique<LasRecordReader>(std::move(src));
    } catch (const CloudError& e) {
      throw CloudError(name_ + ": " + e.what());
    }
  }
  void refill() {
    try {
      held_ = reader_->read(records_.data(), batch_);
      next_ = 0;
    } catch (const CloudError& e) {
      held_ = next_ = 0;
      throw CloudError(name_ + ": " + e.what());
    }
  }

  std::string name_;
  std::unique_ptr<std::string> owned_;  // stdin's bytes
  std::unique_ptr<LasRecordReader> reader_;
  CloudHeader header_;
  std::vector<uint8_t> records_;
  size_t batch_ = 1, held_ = 0, next_ = 0;
};

std::string file_head(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return "";
  char buf[kSniffBytes];
  const size_t n = std::fread(buf, 1, sizeof buf, f);
  std::fclose(f);
  return std::string(buf, n);
}

std::unique_ptr<PointSource> whole_cloud(const std::string& path, const std::string& format) {
  std::vector<double> xyz;
  std::string error;
  if (!read_cloud(path, &xyz, &error)) throw CloudError(error);
  CloudHeader h;
  h.format = format;
  h.count_known = true;
  h.point_count = xyz.size() / 3u;
  return std::make_unique<WholeCloudSource>(std::move(h), std::move(xyz));
}

std::unique_ptr<PointSource> open_stdin() {
  auto bytes = std::make_unique<std::string>();
  std::string error;
  char chunk[1 << 16];
  for (size_t got; (got = std::fread(chunk, 1, sizeof chunk, stdin)) > 0;) {
    if (bytes->size() + got > kMaxCloudFileBytes) throw CloudError(std::string(kStdinName) + " is too large");
    bytes->append(chunk, got);
  }
  if (is_las(*bytes)) {
    auto src = memory_source(*bytes);
    return std::make_unique<LasSource>(kStdinName, std::move(bytes), std::move(src));
  }
  std::vector<double> xyz;
  if (!parse_cloud(*bytes, &xyz, &error)) throw CloudError(std::string(kStdinName) + ": " + error);
  CloudHeader h;
  h.format = is_ply(*bytes) ? "ply" : "text";
  h.count_known = true;
  h.point_count = xyz.size() / 3u;
  return std::make_unique<WholeCloudSource>(std::move(h), std::move(xyz));
}

}  // namespace

std::unique_ptr<PointSource> open_point_source(const std::string& path) {
  if (path == kStdinPath) return open_stdin();
  const std::string head = file_head(path);
  switch (sniff_cloud_format(head)) {
    case CloudFormat::kLas: return std::make_unique<LasSource>(path, nullptr, file_source(path));
    case CloudFormat::kPly: return whole_cloud(path, "ply");
    default: return whole_cloud(path, "text");  // read_cloud names foreign formats
  }
}

CloudHeader read_cloud_header(const std::string& path) { return open_point_source(path)->header(); }

}  // namespace spinhash::host
