// Every source reads a ByteSource (a file, or bytes in memory for standard
// input and fuzzing). LAS and LAZ are read in chunks through LasRecordReader
// (a LAZ chunk is decoded at a time), text a line at a time through a 64 KiB
// window, binary PLY of one vertex element of scalars (what scanners and
// `spinhash scan` write) in chunks of records. Other PLY (ascii, faces) and
// PLY whose sizes do not add up are parsed whole (the parser then names
// what is wrong).
#include "cloud/point_source.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

#include "blob/file_io.hpp"
#include "cloud/byte_source.hpp"
#include "cloud/format_sniff.hpp"
#include "cloud/las_points.hpp"
#include "cloud/ply_body.hpp"
#include "cloud/ply_header.hpp"
#include "cloud/text_cloud.hpp"

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
  LasSource(std::string name, std::unique_ptr<ByteSource> src, const PointFilter& filter)
      : name_(std::move(name)), reader_(named(std::move(src))), filter_(filter) {
    header_ = las_cloud_header(*reader_);
    batch_ = las_batch_records(reader_->header());
    records_.resize(batch_ * reader_->header().record_length);
  }
  const CloudHeader& header() const override { return header_; }
  size_t read(double* xyz, size_t max_points) override {
    const LasHeader& h = reader_->header();
    size_t done = 0;
    while (done < max_points) {
      if (next_ == held_) refill();
      if (held_ == 0) break;
      for (; next_ < held_ && done < max_points; ++next_) {
        const uint8_t* record = records_.data() + next_ * h.record_length;
        if (las_record_dropped(h, record, filter_)) {
          ++noise_;
          continue;
        }
        las_record_xyz(h, record, xyz + 3 * done++);
      }
    }
    return done;
  }
  uint64_t points_noise() const override { return noise_; }

 private:
  std::unique_ptr<LasRecordReader> named(std::unique_ptr<ByteSource> src) {
    try {
      return std::make_unique<LasRecordReader>(std::move(src), laz::LayerChoice::kPipeline);
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
  std::unique_ptr<LasRecordReader> reader_;
  PointFilter filter_;
  CloudHeader header_;
  std::vector<uint8_t> records_;
  size_t batch_ = 1, held_ = 0, next_ = 0;
  uint64_t noise_ = 0;
};

// Text window and the longest line it takes (a point is a few dozen bytes).
constexpr size_t kTextWindow = size_t{1} << 16;
constexpr size_t kMaxTextLine = size_t{1} << 20;

class TextSource final : public PointSource {
 public:
  TextSource(std::string name, std::unique_ptr<ByteSource> src)
      : path_(std::move(name)), src_(std::move(src)) {
    header_.format = "text";
    const std::string head = window(0);
    if (head.find('\0') != std::string::npos) fail(kTextBinaryMessage);
  }
  const CloudHeader& header() const override { return header_; }
  size_t read(double* xyz, size_t max_points) override {
    size_t n = 0;
    std::string line;
    while (n < max_points && next_line(&line)) {
      bool has_point = false;
      std::string error;
      if (!parser_.line(line, xyz + 3 * n, &has_point, &error)) fail(error);
      if (has_point) ++n;
    }
    points_ += n;
    if (n == 0 && points_ == 0 && max_points > 0) fail(kTextEmptyMessage);
    return n;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw CloudError(path_ + ": " + why); }
  std::string window(uint64_t at) const {
    std::string w(static_cast<size_t>(std::min<uint64_t>(kTextWindow, src_->size() - at)), '\0');
    if (!w.empty()) src_->read_at(at, w.data(), w.size());
    return w;
  }
  // The next line without its '\n'; false at the end of the file.
  bool next_line(std::string* line) {
    line->clear();
    for (;;) {
      if (pos_ == buffer_.size()) {
        if (offset_ >= src_->size()) return !line->empty();
        buffer_ = window(offset_);
        offset_ += buffer_.size();
        pos_ = 0;
      }
      const size_t end = buffer_.find('\n', pos_);
      const size_t stop = end == std::string::npos ? buffer_.size() : end;
      line->append(buffer_, pos_, stop - pos_);
      if (line->size() > kMaxTextLine) fail("a line longer than " + std::to_string(kMaxTextLine) + " bytes");
      pos_ = end == std::string::npos ? buffer_.size() : end + 1;
      if (end != std::string::npos) return true;
    }
  }

  std::string path_;
  std::unique_ptr<ByteSource> src_;
  CloudHeader header_;
  TextCloudParser parser_;
  std::string buffer_;
  size_t pos_ = 0;
  uint64_t offset_ = 0, points_ = 0;
};

// Binary PLY whose only element is the vertex, every property a scalar, the
// data exactly count records long, x y z float or double.
class PlySource final : public PointSource {
 public:
  static constexpr size_t kBatchBytes = size_t{1} << 20;

  // nullptr (src untouched) when the file is not of that simple kind.
  static std::unique_ptr<PlySource> open(std::unique_ptr<ByteSource>& src) {
    std::string head(static_cast<size_t>(std::min<uint64_t>(src->size(), ply::kMaxHeaderBytes)), '\0');
    if (!head.empty()) src->read_at(0, head.data(), head.size());
    ply::Header h;
    std::string error;
    if (!ply::parse_header(head, &h, &error) || h.format == ply::Format::kAscii || h.elements.size() != 1 ||
        h.elements[0].name != "vertex")
      return nullptr;
    auto s = std::unique_ptr<PlySource>(new PlySource(std::move(src), h));
    if (s->usable()) return s;
    src = std::move(s->src_);
    return nullptr;
  }
  const CloudHeader& header() const override { return header_; }
  size_t read(double* xyz, size_t max_points) override {
    const size_t n = static_cast<size_t>(std::min<uint64_t>({max_points, left_, batch_}));
    if (n == 0) return 0;
    src_->read_at(next_offset_, buffer_.data(), n * record_);
    for (size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a)
        xyz[3 * i + a] =
            ply::binary_value(axis_type_[a], buffer_.data() + i * record_ + axis_at_[a], big_endian_);
    next_offset_ += n * record_;
    left_ -= n;
    return n;
  }

 private:
  PlySource(std::unique_ptr<ByteSource> src, const ply::Header& h)
      : src_(std::move(src)), big_endian_(h.format == ply::Format::kBinaryBigEndian) {
    const ply::Element& e = h.elements[0];
    size_t at = 0;
    int found = 0;
    scalars_ = true;
    for (const ply::Property& p : e.properties) {
      scalars_ = scalars_ && !p.is_list;
      for (int a = 0; a < 3; ++a)
        if (p.name == std::string(1, static_cast<char>('x' + a)) && !p.is_list && !ply::is_integer(p.type)) {
          axis_at_[a] = at;
          axis_type_[a] = p.type;
          ++found;
        }
      at += ply::type_size(p.type);
    }
    record_ = at;
    axes_ = found == 3;
    next_offset_ = h.data_offset;
    left_ = e.count;
    header_.format = "ply";
    header_.count_known = true;
    header_.point_count = e.count;
  }
  bool usable() {
    if (!scalars_ || !axes_ || record_ == 0 || next_offset_ > src_->size()) return false;
    const uint64_t data = src_->size() - next_offset_;
    if (data % record_ != 0 || data / record_ != left_) return false;
    batch_ = std::max<size_t>(1, kBatchBytes / record_);
    buffer_.resize(static_cast<size_t>(std::min<uint64_t>(batch_, std::max<uint64_t>(left_, 1))) * record_);
    batch_ = buffer_.size() / record_;
    return true;
  }

  std::unique_ptr<ByteSource> src_;
  bool big_endian_;
  bool scalars_ = false, axes_ = false;
  size_t axis_at_[3] = {0, 0, 0};
  ply::Type axis_type_[3] = {ply::Type::kFloat32, ply::Type::kFloat32, ply::Type::kFloat32};
  size_t record_ = 0, batch_ = 1;
  uint64_t next_offset_ = 0, left_ = 0;
  std::vector<uint8_t> buffer_;
  CloudHeader header_;
};

std::string head_of(ByteSource& src) {
  std::string head(static_cast<size_t>(std::min<uint64_t>(src.size(), kSniffBytes)), '\0');
  if (!head.empty()) src.read_at(0, head.data(), head.size());
  return head;
}

// A PLY the chunked reader does not take, parsed whole.
std::unique_ptr<PointSource> whole_ply(const std::string& name, ByteSource& src) {
  if (src.size() > kMaxCloudFileBytes)
    throw CloudError(name + ": larger than the limit of " + std::to_string(kMaxCloudFileBytes) + " bytes");
  std::string bytes(static_cast<size_t>(src.size()), '\0');
  if (!bytes.empty()) src.read_at(0, bytes.data(), bytes.size());
  ply::Header header;
  std::vector<double> xyz;
  std::string error;
  if (!ply::parse_header(bytes, &header, &error) || !ply::read_body(bytes, header, &xyz, &error))
    throw CloudError(name + ": " + error);
  CloudHeader h;
  h.format = "ply";
  h.count_known = true;
  h.point_count = xyz.size() / 3u;
  return std::make_unique<WholeCloudSource>(std::move(h), std::move(xyz));
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// A file whose name promises a format its content does not have: refused
// rather than read as text (a download that saved an error page as .laz).
void check_named_format(const std::string& name, const std::string& path, const std::string& head,
                        SniffedFormat sniffed) {
  const std::string ext = lower_extension(path);
  const bool las_name = ext == ".las" || ext == ".laz";
  if ((las_name && sniffed != SniffedFormat::kLas) || (ext == ".ply" && sniffed != SniffedFormat::kPly)) {
    const bool text = head.find('\0') == std::string::npos;
    throw CloudError(name + ": named " + ext + " but not " + (las_name ? "LAS/LAZ" : "PLY") +
                     ": it does not start with " +
                     (las_name ? "the signature \"LASF\"" : "the line \"ply\"") +
                     (text ? " (it holds text: an error page or a listing saved under this name?)" : ""));
  }
}

std::unique_ptr<PointSource> open_source(const std::string& name, const std::string& path,
                                         std::unique_ptr<ByteSource> src, const PointFilter& filter) {
  const std::string head = head_of(*src);
  const SniffedFormat sniffed = sniff_cloud_format(head);
  if (sniffed == SniffedFormat::kForeign)
    throw CloudError(name + ": not a point cloud this reader takes: " + foreign_cloud_format(head));
  check_named_format(name, path, head, sniffed);
  switch (sniffed) {
    case SniffedFormat::kLas: return std::make_unique<LasSource>(name, std::move(src), filter);
    case SniffedFormat::kPly: {
      if (auto ply = PlySource::open(src)) return ply;
      return whole_ply(name, *src);
    }
    default: return std::make_unique<TextSource>(name, std::move(src));
  }
}

}  // namespace

std::string cloud_name(const std::string& path) {
  return path == kStdinPath ? kStdinName : std::filesystem::path(path).stem().string();
}

std::unique_ptr<PointSource> open_point_source(const std::string& path, const PointFilter& filter) {
  if (path != kStdinPath) return open_source(path, path, file_source(path), filter);
  std::string bytes, error;
  if (!read_file(kStdinPath, kMaxCloudFileBytes, &bytes, &error)) throw CloudError(error);
  return open_point_source_bytes(std::move(bytes), kStdinName, filter);
}

std::unique_ptr<PointSource> open_point_source_bytes(std::string bytes, const std::string& name,
                                                     const PointFilter& filter) {
  return open_source(name, "", owned_memory_source(std::move(bytes)), filter);
}

CloudHeader read_cloud_header(const std::string& path) { return open_point_source(path)->header(); }

std::vector<double> read_all_points(PointSource& source) {
  std::vector<double> xyz;
  std::vector<double> chunk(3 * kDefaultChunkPoints);
  for (size_t got; (got = source.read(chunk.data(), kDefaultChunkPoints)) > 0;)
    xyz.insert(xyz.end(), chunk.begin(), chunk.begin() + static_cast<long>(3 * got));
  return xyz;
}

}  // namespace spinhash::host
