#include "cloud/laz/laz_decoder.hpp"

#include <algorithm>

#include "cloud/cloud_error.hpp"

namespace spinhash::host::laz {
namespace {

constexpr size_t kCountBytes = 4;  // a layered chunk's point count, each layer's size

uint32_t le32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
         (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}

}  // namespace

// Streams [begin, end) of the file through a fixed window.
class LazDecoder::Feed final : public ByteFeed {
 public:
  Feed(ByteSource& src, uint64_t begin, uint64_t end)
      : src_(src), next_(begin), end_(end), buf_(kFeedBytes) {}
  bool refill(const uint8_t** begin, const uint8_t** end) override {
    if (next_ >= end_) return false;
    const size_t n = static_cast<size_t>(std::min<uint64_t>(buf_.size(), end_ - next_));
    src_.read_at(next_, buf_.data(), n);
    next_ += n;
    *begin = buf_.data();
    *end = buf_.data() + n;
    return true;
  }

 private:
  ByteSource& src_;
  uint64_t next_, end_;
  std::vector<uint8_t> buf_;
};

LazDecoder::LazDecoder(ByteSource& src, uint64_t points_offset, uint64_t point_count, uint16_t record_length,
                       const LaszipVlr& vlr, LayerChoice choice)
    : src_(src),
      vlr_(vlr),
      choice_(choice),
      record_length_(record_length),
      points_offset_(points_offset),
      remaining_(point_count) {
  size_t at = 0;
  for (const LazItem& item : vlr_.items) {
    item_offsets_.push_back(at);
    at += item.size;
    if (vlr_.layered())
      layered_.push_back(make_layered_item(item));
    else
      pointwise_.push_back(make_pointwise_item(item));
  }
  for (const auto& item : pointwise_) pointwise_items_.push_back(item.get());
}

// The chunk table is read with the first point: a header alone never needs it.
void LazDecoder::locate_chunks() {
  located_ = true;
  if (vlr_.chunked()) {
    chunks_ = read_chunk_table(src_, points_offset_, vlr_, remaining_);
  } else {
    if (points_offset_ >= src_.size()) fail("the file ends before its compressed points");
    chunks_.push_back({points_offset_, src_.size() - points_offset_, remaining_});
  }
}

LazDecoder::~LazDecoder() = default;

void LazDecoder::fail(const std::string& why) const {
  throw CloudError("LAZ: chunk " + std::to_string(chunk_) + " of " + std::to_string(chunks_.size()) + ": " +
                   why);
}

size_t LazDecoder::read(uint8_t* out, size_t max) {
  size_t n = 0;
  if (!located_ && remaining_ > 0 && max > 0) locate_chunks();
  while (n < max && remaining_ > 0) {
    uint8_t* record = out + n * record_length_;
    size_t run = 1;
    if (left_in_chunk_ == 0) {
      start_chunk(record);
    } else {
      // The chunk's points in one run: the counts move once a run.
      run = static_cast<size_t>(std::min<uint64_t>(std::min<uint64_t>(max - n, left_in_chunk_), remaining_));
      decode_run(record, run);
    }
    left_in_chunk_ -= run;
    remaining_ -= run;
    n += run;
  }
  return n;
}

void LazDecoder::start_chunk(uint8_t* first) {
  if (started_) ++chunk_;
  started_ = true;
  if (chunk_ >= chunks_.size()) fail("the chunks end before the header's point count");
  const ChunkEntry& c = chunks_[chunk_];
  if (c.points > std::max<uint64_t>(c.bytes, 1) * kMaxPointsPerByte)
    fail(std::to_string(c.points) + " points cannot be coded in " + std::to_string(c.bytes) + " bytes");
  left_in_chunk_ = c.points;
  if (vlr_.layered())
    start_layered(first);
  else
    start_pointwise(first);
}

void LazDecoder::start_pointwise(uint8_t* first) {
  const ChunkEntry& c = chunks_[chunk_];
  feed_ = std::make_unique<Feed>(src_, c.offset, c.offset + c.bytes);
  dec_.attach(nullptr, nullptr, feed_.get());
  if (!dec_.take_raw(first, record_length_)) fail("the data ends inside the chunk's first point");
  for (size_t i = 0; i < pointwise_.size(); ++i) pointwise_[i]->init(first + item_offsets_[i]);
  dec_.start();
}

void LazDecoder::start_layered(uint8_t* first) {
  const ChunkEntry& c = chunks_[chunk_];
  chunk_bytes_.resize(static_cast<size_t>(c.bytes));
  src_.read_at(c.offset, chunk_bytes_.data(), chunk_bytes_.size());
  const uint8_t* p = chunk_bytes_.data();
  const uint8_t* end = p + chunk_bytes_.size();
  if (static_cast<size_t>(end - p) < record_length_ + kCountBytes)
    fail("the data ends inside the first point");
  std::copy(p, p + record_length_, first);
  p += record_length_;
  const uint32_t count = le32(p);
  p += kCountBytes;
  if (count != c.points)
    fail("the chunk says it holds " + std::to_string(count) + " points, the chunk table " +
         std::to_string(c.points));
  size_t layer_total = 0;
  for (const auto& item : layered_) layer_total += item->layer_count();
  if (static_cast<size_t>(end - p) / kCountBytes < layer_total) fail("the data ends inside the layer sizes");
  layers_.assign(layer_total, Layer{});
  for (Layer& l : layers_) {
    l.size = le32(p);
    p += kCountBytes;
  }
  for (Layer& l : layers_) {
    if (l.size > static_cast<size_t>(end - p))
      fail("a layer of " + std::to_string(l.size) + " bytes runs past the chunk");
    l.begin = p;
    p += l.size;
  }
  context_ = 0;
  size_t layer = 0;
  for (size_t i = 0; i < layered_.size(); ++i) {
    Layer* own = layers_.data() + layer;
    if (choice_ == LayerChoice::kPipeline)
      for (size_t k = 0; k < layered_[i]->layer_count(); ++k)
        if (!layered_[i]->pipeline_layer(k)) own[k].size = 0;  // decoded as an unchanging field
    layered_[i]->init(first + item_offsets_[i], own, &context_);
    layer += layered_[i]->layer_count();
  }
}

void LazDecoder::decode_run(uint8_t* out, size_t count) {
  size_t done = 0;
  try {
    if (!vlr_.layered()) {
      PointwiseItem* const* items = pointwise_items_.data();
      const size_t* offsets = item_offsets_.data();
      const size_t item_count = pointwise_items_.size();
      for (; done < count; ++done, out += record_length_) {
        for (size_t i = 0; i < item_count; ++i) items[i]->decode(dec_, out + offsets[i]);
        if (dec_.overrun() > kOverrunSlack)
          fail("the compressed data ends before the chunk's points (truncated?)");
      }
      return;
    }
    for (; done < count; ++done, out += record_length_)
      for (size_t i = 0; i < layered_.size(); ++i) {
        layered_[i]->decode(out + item_offsets_[i], &context_);
        if (layered_[i]->overrun() > kOverrunSlack)
          fail("a layer of item " + item_name(vlr_.items[i].type) +
               " ends before the chunk's points (truncated?)");
      }
  } catch (...) {
    // The points decoded before the failure count as handed out.
    left_in_chunk_ -= done;
    remaining_ -= done;
    throw;
  }
}

}  // namespace spinhash::host::laz
