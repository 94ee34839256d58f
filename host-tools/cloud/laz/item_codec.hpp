// The per-item decoders of a LASzip point. A point is a sequence of items
// (POINT10, GPSTIME11, RGB12, BYTE for formats 0-5; POINT14, RGB14,
// RGBNIR14, BYTE14 for 6-10), each decoded into its bytes of the raw LAS
// record. The first point of a chunk is stored raw and seeds every item.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "cloud/laz/arithmetic_decoder.hpp"
#include "cloud/laz/laszip_vlr.hpp"

namespace spinhash::host::laz {

// Compressors 1 and 2: every item reads from the one decoder of the chunk.
class PointwiseItem {
 public:
  virtual ~PointwiseItem() = default;
  virtual void init(const uint8_t* first) = 0;  // the chunk's raw first item
  virtual void decode(ArithmeticDecoder& dec, uint8_t* out) = 0;
};

// A layer's bytes inside a layered chunk.
struct Layer {
  const uint8_t* begin = nullptr;
  size_t size = 0;
};

// Compressor 3: each item owns one or more layers, each with its own
// decoder; POINT14 sets the scanner-channel context the other items follow.
class LayeredItem {
 public:
  virtual ~LayeredItem() = default;
  virtual size_t layer_count() const = 0;
  // layers[0 .. layer_count()) for this chunk; `context` is read (and, by
  // POINT14, written).
  virtual void init(const uint8_t* first, const Layer* layers, uint32_t* context) = 0;
  virtual void decode(uint8_t* out, uint32_t* context) = 0;
  // The most bytes any of the item's decoders read past its layer.
  virtual size_t overrun() const = 0;
  // Layer `layer` codes a field the pipeline takes (x y z, the return
  // numbers, the class and its flags): LayerChoice::kPipeline decodes only
  // these.
  virtual bool pipeline_layer(size_t layer) const = 0;
};

// Throws CloudError for an item this reader does not decode (the VLR check
// refuses those first, so this is a second line).
std::unique_ptr<PointwiseItem> make_pointwise_item(const LazItem& item);
std::unique_ptr<LayeredItem> make_layered_item(const LazItem& item);

// Item factories, one per file.
std::unique_ptr<PointwiseItem> make_point10(uint16_t version);
std::unique_ptr<PointwiseItem> make_gpstime11(uint16_t version);
std::unique_ptr<PointwiseItem> make_rgb12(uint16_t version);
std::unique_ptr<PointwiseItem> make_byte(uint16_t version, uint16_t count);
std::unique_ptr<LayeredItem> make_point14(uint16_t version);
std::unique_ptr<LayeredItem> make_rgb14(uint16_t version, bool nir);
std::unique_ptr<LayeredItem> make_byte14(uint16_t version, uint16_t count);

// Byte helpers shared by the item files.
inline uint8_t u8_fold(int32_t v) { return static_cast<uint8_t>(v < 0 ? v + 256 : (v > 255 ? v - 256 : v)); }
inline int32_t u8_clamp(int32_t v) { return v < 0 ? 0 : (v > 255 ? 255 : v); }
inline uint16_t get_u16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
inline void put_u16(uint8_t* p, uint32_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}
inline int32_t get_i32(const uint8_t* p) {
  return static_cast<int32_t>(static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
                              (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24));
}
inline void put_i32(uint8_t* p, int32_t v) {
  const uint32_t u = static_cast<uint32_t>(v);
  for (int i = 0; i < 4; ++i) p[i] = static_cast<uint8_t>(u >> (8 * i));
}
inline uint64_t get_u64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
inline void put_u64(uint8_t* p, uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}

// The streaming median of the last five values (LASzip's predictor of x
// and y differences).
class Median5 {
 public:
  void reset() {
    for (int32_t& v : values_) v = 0;
    high_ = true;
  }
  int32_t get() const { return values_[2]; }
  void add(int32_t v);

 private:
  int32_t values_[5] = {0, 0, 0, 0, 0};
  bool high_ = true;
};

// v into the sorted pair (a, b): the three in order, written at out.
inline void insert_into_pair(int32_t a, int32_t b, int32_t v, int32_t* out) {
  out[0] = std::min(v, a);
  out[1] = std::max(a, std::min(v, b));
  out[2] = std::max(v, b);
}

// The values stay sorted; each case below is LASzip's insertion written
// as minima and maxima (selects, not branches: the differences come in no
// predictable order).
inline void Median5::add(int32_t v) {
  int32_t* x = values_;
  if (high_ && v < x[2]) {  // into the lower three; the top two shift up
    x[4] = x[3];
    x[3] = x[2];
    insert_into_pair(x[0], x[1], v, x);
  } else if (high_) {  // into the top two, the largest dropped
    const int32_t c = x[3];
    x[3] = std::min(v, c);
    x[4] = std::max(v, c);
    high_ = false;
  } else if (x[2] < v) {  // into the upper three; the bottom two shift down
    x[0] = x[1];
    x[1] = x[2];
    insert_into_pair(x[3], x[4], v, x + 2);
  } else {  // into the bottom two, the smallest dropped
    const int32_t b = x[1];
    x[0] = std::min(v, b);
    x[1] = std::max(v, b);
    high_ = true;
  }
}

}  // namespace spinhash::host::laz
