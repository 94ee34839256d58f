// RGB14 and RGBNIR14: the colour (and near infrared) of formats 7 and 8, one
// layer for RGB and one for NIR, a context per scanner channel. Version 3
// keeps the previous channel's last colour as the prediction when it
// switches to a channel already seen (LASzip's writer did the same until
// version 4 fixed it), version 4 takes the channel's own.
#include <array>

#include "cloud/laz/item_codec.hpp"
#include "cloud/laz/rgb_codec.hpp"

namespace spinhash::host::laz {
namespace {

constexpr uint32_t kChannels = 4;
constexpr uint32_t kNirByteUsedSymbols = 4;
constexpr uint32_t kByteSymbols = 256;
constexpr size_t kRgbBytes = 6;

struct ColourContext {
  bool used = false;
  uint16_t last[4] = {};  // r g b nir
  RgbDecoder rgb;
  SymbolModel nir_used{kNirByteUsedSymbols};
  SymbolModel nir_diff[2] = {SymbolModel(kByteSymbols), SymbolModel(kByteSymbols)};

  void reset(const uint16_t* seed) {
    rgb.reset();
    nir_used.reset();
    nir_diff[0].reset();
    nir_diff[1].reset();
    std::copy(seed, seed + 4, last);
    used = true;
  }
};

class Rgb14Item final : public LayeredItem {
 public:
  Rgb14Item(uint16_t version, bool nir) : fixed_switch_(version >= 4), nir_(nir) {}
  size_t layer_count() const override { return nir_ ? 2 : 1; }

  void init(const uint8_t* first, const Layer* layers, uint32_t* context) override {
    has_rgb_ = layers[0].size > 0;
    if (has_rgb_) dec_[0].init(layers[0].begin, layers[0].begin + layers[0].size);
    has_nir_ = nir_ && layers[1].size > 0;
    if (has_nir_) dec_[1].init(layers[1].begin, layers[1].begin + layers[1].size);
    uint16_t seed[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < (nir_ ? 4u : 3u); ++i) seed[i] = get_u16(first + 2 * i);
    for (auto& c : contexts_) c.used = false;
    current_ = *context % kChannels;
    contexts_[current_].reset(seed);
  }

  void decode(uint8_t* out, uint32_t* context) override {
    uint16_t* last = contexts_[current_].last;
    const uint32_t wanted = *context % kChannels;
    if (wanted != current_) {
      current_ = wanted;
      ColourContext& next = contexts_[wanted];
      if (!next.used) {
        next.reset(last);
        last = next.last;
      } else if (fixed_switch_) {
        last = next.last;
      }
    }
    ColourContext& c = contexts_[current_];
    if (has_rgb_) {
      uint16_t rgb[3];
      c.rgb.decode(dec_[0], last, rgb);
      for (int i = 0; i < 3; ++i) last[i] = rgb[i];
    }
    for (int i = 0; i < 3; ++i) put_u16(out + 2 * i, last[i]);
    if (!nir_) return;
    if (has_nir_) last[3] = decode_nir(c, last[3]);
    put_u16(out + kRgbBytes, last[3]);
  }

  size_t overrun() const override { return std::max(dec_[0].overrun(), dec_[1].overrun()); }
  // Colour is not the pipeline's.
  bool pipeline_layer(size_t /*layer*/) const override { return false; }

 private:
  uint16_t decode_nir(ColourContext& c, uint16_t last) {
    const uint32_t sym = dec_[1].decode_symbol(c.nir_used);
    int32_t lo = last & 0xFF, hi = last >> 8;
    if (sym & 1u) lo = u8_fold(static_cast<int32_t>(dec_[1].decode_symbol(c.nir_diff[0])) + lo);
    if (sym & 2u) hi = u8_fold(static_cast<int32_t>(dec_[1].decode_symbol(c.nir_diff[1])) + hi);
    return static_cast<uint16_t>(lo | (hi << 8));
  }

  bool fixed_switch_, nir_;
  bool has_rgb_ = false, has_nir_ = false;
  ArithmeticDecoder dec_[2];
  std::array<ColourContext, kChannels> contexts_;
  uint32_t current_ = 0;
};

}  // namespace

std::unique_ptr<LayeredItem> make_rgb14(uint16_t version, bool nir) {
  return std::make_unique<Rgb14Item>(version, nir);
}

}  // namespace spinhash::host::laz
