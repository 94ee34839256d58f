#include "cloud/las_points.hpp"

#include <algorithm>
#include <cstring>

#include "cloud/cloud_error.hpp"
#include "cloud/las_crs.hpp"
#include "cloud/laz/laszip_vlr.hpp"
#include "cloud/laz/laz_decoder.hpp"

namespace spinhash::host {
namespace {

// The header may be padded up to its 16-bit size: read that much at most.
constexpr size_t kMaxHeaderBytes = size_t{1} << 16;
constexpr uint8_t kLegacyClassMask = 0x1F;              // formats 0-5: 5 bits of class, 3 of flags
constexpr size_t kLegacyClassAt = 15, kClassAt14 = 16;  // byte of a record holding the class
constexpr size_t kReturnAt = 14;
constexpr uint8_t kLegacyReturnMask = 0x07, kReturnMask14 = 0x0F;
constexpr size_t kClassFlagsAt14 = 15;  // formats 6-10: the class flags' byte
constexpr uint8_t kLegacyWithheld = 0x80, kWithheld14 = 0x04;

int32_t le_int32(const uint8_t* p) {
  const uint32_t u = static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
                     (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
  int32_t v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

LasHeader read_header(ByteSource& src) {
  std::vector<uint8_t> head(static_cast<size_t>(std::min<uint64_t>(src.size(), kMaxHeaderBytes)));
  if (!head.empty()) src.read_at(0, head.data(), head.size());
  return parse_las_header(head.data(), head.size(), src.size());
}

}  // namespace

LasRecordReader::LasRecordReader(std::unique_ptr<ByteSource> src, laz::LayerChoice layers)
    : src_(std::move(src)) {
  header_ = read_header(*src_);
  vlrs_ = read_vlrs(*src_, header_, &crs_.warnings);
  const std::vector<std::string> vlr_warnings = crs_.warnings;
  crs_ = las_crs(header_, vlrs_);
  crs_.warnings.insert(crs_.warnings.begin(), vlr_warnings.begin(), vlr_warnings.end());
  left_ = header_.point_count;
  next_offset_ = header_.offset_to_points;
  if (!header_.compressed) return;
  const Vlr* v = find_vlr(vlrs_, laz::kLaszipUserId, laz::kLaszipRecordId);
  if (v == nullptr)
    throw CloudError(
        "LAS: compressed (LAZ) point data without a LASzip VLR (user id \"laszip encoded\", record 22204): "
        "this is no LAZ file this reader can decode");
  const laz::LaszipVlr lv =
      laz::parse_laszip_vlr(v->data.data(), v->data.size(), header_.point_format, header_.record_length);
  if (header_.record_length < kLasMinRecordLength[header_.point_format])
    throw CloudError("LAS: point record length " + std::to_string(header_.record_length) +
                     " is below format " + std::to_string(header_.point_format) + "'s " +
                     std::to_string(kLasMinRecordLength[header_.point_format]));
  laz_ = std::make_unique<laz::LazDecoder>(*src_, header_.offset_to_points, header_.point_count,
                                           header_.record_length, lv, layers);
}

LasRecordReader::~LasRecordReader() = default;

size_t LasRecordReader::read(uint8_t* out, size_t max) {
  const size_t n = static_cast<size_t>(std::min<uint64_t>(max, left_));
  if (n == 0) return 0;
  if (laz_) {
    const size_t got = laz_->read(out, n);
    left_ -= got;
    return got;
  }
  src_->read_at(next_offset_, out, n * header_.record_length);
  next_offset_ += static_cast<uint64_t>(n) * header_.record_length;
  left_ -= n;
  return n;
}

size_t las_batch_records(const LasHeader& h) {
  const size_t by_bytes = std::max<size_t>(1, kLasBatchBytes / std::max<size_t>(1, h.record_length));
  const size_t by_count =
      static_cast<size_t>(std::max<uint64_t>(1, std::min<uint64_t>(h.point_count, kLasBatchRecords)));
  return std::min(by_bytes, by_count);
}

void las_record_xyz(const LasHeader& h, const uint8_t* record, double* xyz) {
  for (int a = 0; a < 3; ++a)
    xyz[a] = static_cast<double>(le_int32(record + 4 * a)) * h.scale[a] + h.offset[a];
}

uint8_t las_record_class(const LasHeader& h, const uint8_t* record) {
  if (h.point_format >= kLasFirstFormat14) return record[kClassAt14];
  return record[kLegacyClassAt] & kLegacyClassMask;
}

bool las_record_dropped(const LasHeader& h, const uint8_t* record, const PointFilter& filter) {
  const bool withheld = h.point_format >= kLasFirstFormat14 ? (record[kClassFlagsAt14] & kWithheld14) != 0
                                                            : (record[kLegacyClassAt] & kLegacyWithheld) != 0;
  return withheld || filter.drops(las_record_class(h, record));
}

uint8_t las_record_return(const LasHeader& h, const uint8_t* record) {
  return record[kReturnAt] & (h.point_format >= kLasFirstFormat14 ? kReturnMask14 : kLegacyReturnMask);
}

}  // namespace spinhash::host
