// RGB12: the red, green and blue of formats 2, 3 and 5 (three u16).
#include "cloud/laz/integer_decompressor.hpp"
#include "cloud/laz/item_codec.hpp"
#include "cloud/laz/rgb_codec.hpp"

namespace spinhash::host::laz {
namespace {

constexpr int kChannels = 3;

void load(const uint8_t* p, uint16_t* rgb) {
  for (int i = 0; i < kChannels; ++i) rgb[i] = get_u16(p + 2 * i);
}
void store(const uint16_t* rgb, uint8_t* p) {
  for (int i = 0; i < kChannels; ++i) put_u16(p + 2 * i, rgb[i]);
}

class Rgb12V2 final : public PointwiseItem {
 public:
  void init(const uint8_t* first) override {
    codec_.reset();
    load(first, last_);
  }
  void decode(ArithmeticDecoder& dec, uint8_t* out) override {
    uint16_t rgb[kChannels];
    codec_.decode(dec, last_, rgb);
    store(rgb, out);
    for (int i = 0; i < kChannels; ++i) last_[i] = rgb[i];
  }

 private:
  RgbDecoder codec_;
  uint16_t last_[kChannels] = {};
};

// Version 1: each of the six bytes that changed is an integer correction of
// its last value, one context per byte.
constexpr uint32_t kV1ByteUsedSymbols = 64;
constexpr int kColourBytes = 6;

class Rgb12V1 final : public PointwiseItem {
 public:
  void init(const uint8_t* first) override {
    byte_used_.reset();
    ic_.reset();
    std::copy(first, first + kColourBytes, last_);
  }
  void decode(ArithmeticDecoder& dec, uint8_t* out) override {
    const uint32_t sym = dec.decode_symbol(byte_used_);
    for (int b = 0; b < kColourBytes; ++b) {
      // Byte b is channel b/2's low (even b) or high (odd b) byte: little-endian order.
      const bool changed = (sym >> b) & 1u;
      out[b] =
          changed ? static_cast<uint8_t>(ic_.decompress(dec, last_[b], static_cast<uint32_t>(b))) : last_[b];
    }
    std::copy(out, out + kColourBytes, last_);
  }

 private:
  SymbolModel byte_used_{kV1ByteUsedSymbols};
  IntegerDecompressor ic_{8, kColourBytes};
  uint8_t last_[kColourBytes] = {};
};

}  // namespace

std::unique_ptr<PointwiseItem> make_rgb12(uint16_t version) {
  if (version == 1) return std::make_unique<Rgb12V1>();
  return std::make_unique<Rgb12V2>();
}

}  // namespace spinhash::host::laz
