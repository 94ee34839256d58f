// The point records of a LAS or LAZ file, read in chunks: raw records (the
// bytes of the uncompressed file, whether read or decoded), and the fields
// the pipeline takes from them (x y z scaled and offset in double, class,
// return number).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/crs.hpp"
#include "cloud/las_header.hpp"
#include "cloud/las_vlrs.hpp"
#include "cloud/laz/layer_choice.hpp"
#include "cloud/point_filter.hpp"

namespace spinhash::host {

namespace laz {
class LazDecoder;
}

class LasRecordReader {
 public:
  // Reads the header, the VLRs (the CRS, the LASzip record) of src. Throws
  // CloudError ("LAS: ..." / "LAZ: ..."). `layers`: what a LAS 1.4 LAZ
  // file's records hold (laz/layer_choice.hpp); the pipeline's readers ask
  // only for its fields.
  explicit LasRecordReader(std::unique_ptr<ByteSource> src, laz::LayerChoice layers = laz::LayerChoice::kAll);
  ~LasRecordReader();
  const LasHeader& header() const { return header_; }
  const std::vector<Vlr>& vlrs() const { return vlrs_; }
  const Crs& crs() const { return crs_; }
  uint64_t records_left() const { return left_; }
  // Up to max records (header().record_length bytes each) into out; 0 at
  // the end. Throws CloudError on corrupt or truncated data.
  size_t read(uint8_t* out, size_t max);

 private:
  std::unique_ptr<ByteSource> src_;
  LasHeader header_;
  std::vector<Vlr> vlrs_;
  Crs crs_;
  uint64_t next_offset_ = 0;  // uncompressed: the next record
  uint64_t left_ = 0;
  std::unique_ptr<laz::LazDecoder> laz_;
};

// Records per read that keep a batch of raw records near 1 MiB (and no
// larger than the file's count): a 64 KiB record length cannot make a
// small file allocate much.
constexpr size_t kLasBatchRecords = 4096;
constexpr size_t kLasBatchBytes = size_t{1} << 20;
size_t las_batch_records(const LasHeader& h);

// Fields of a raw record of the header's format.
void las_record_xyz(const LasHeader& h, const uint8_t* record, double* xyz);
uint8_t las_record_class(const LasHeader& h, const uint8_t* record);   // formats 0-5: the low 5 bits
uint8_t las_record_return(const LasHeader& h, const uint8_t* record);  // 1-based return number
// The record is one the readers leave out (cloud/point_filter.hpp): the
// withheld flag, or a class the filter drops (ASPRS noise, classes named).
bool las_record_dropped(const LasHeader& h, const uint8_t* record, const PointFilter& filter);

}  // namespace spinhash::host
