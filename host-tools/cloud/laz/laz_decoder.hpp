// Decodes the point records of a LAZ file, a chunk at a time: memory holds
// one chunk (layered) or a 64 KiB window of it (pointwise), never the file.
// The output is the raw LAS point records, byte for byte those of the
// uncompressed file (LayerChoice::kAll; kPipeline: the pipeline's fields),
// so one record-to-xyz path serves LAS and LAZ.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/laz/arithmetic_decoder.hpp"
#include "cloud/laz/chunk_table.hpp"
#include "cloud/laz/item_codec.hpp"
#include "cloud/laz/laszip_vlr.hpp"
#include "cloud/laz/layer_choice.hpp"

namespace spinhash::host::laz {

// Bytes a decoder may read past its data before the data counts as
// truncated (a valid stream never reads past its end).
constexpr size_t kOverrunSlack = 8;
// A chunk of identical points costs LASzip's adaptive models about 0.008
// bits a point (the most likely symbol of each model never passes
// 1 - 2^-13 or so), about 1 000 points a byte; four times that is a
// corrupt count, which would otherwise decode garbage for a long time.
constexpr uint64_t kMaxPointsPerByte = 4096;
// The window a pointwise chunk is streamed through.
constexpr size_t kFeedBytes = size_t{1} << 16;

class LazDecoder {
 public:
  // src outlives the decoder. Nothing is read until the first point.
  LazDecoder(ByteSource& src, uint64_t points_offset, uint64_t point_count, uint16_t record_length,
             const LaszipVlr& vlr, LayerChoice choice = LayerChoice::kAll);
  ~LazDecoder();
  // Up to max records (record_length bytes each) into out; 0 at the end.
  // Throws CloudError ("LAZ: chunk i: ...") on corrupt or truncated data.
  size_t read(uint8_t* out, size_t max);
  size_t chunk_count() const { return chunks_.size(); }

 private:
  class Feed;
  void locate_chunks();
  void start_chunk(uint8_t* first);
  void start_pointwise(uint8_t* first);
  void start_layered(uint8_t* first);
  // `count` points of the current chunk, one record after another.
  void decode_run(uint8_t* out, size_t count);
  [[noreturn]] void fail(const std::string& why) const;

  ByteSource& src_;
  LaszipVlr vlr_;
  LayerChoice choice_;
  uint16_t record_length_;
  uint64_t points_offset_;
  bool located_ = false;  // the chunk table has been read
  uint64_t remaining_;    // points still to hand out
  std::vector<ChunkEntry> chunks_;
  size_t chunk_ = 0;
  bool started_ = false;  // chunk_ is being decoded
  uint64_t left_in_chunk_ = 0;
  std::vector<size_t> item_offsets_;
  std::vector<std::unique_ptr<PointwiseItem>> pointwise_;
  std::vector<PointwiseItem*> pointwise_items_;  // pointwise_'s, for the point loop
  std::vector<std::unique_ptr<LayeredItem>> layered_;
  ArithmeticDecoder dec_;
  std::unique_ptr<Feed> feed_;
  std::vector<uint8_t> chunk_bytes_;  // a layered chunk
  std::vector<Layer> layers_;
  uint32_t context_ = 0;
};

}  // namespace spinhash::host::laz
