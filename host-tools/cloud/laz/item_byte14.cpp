// BYTE14: the extra bytes of formats 6-10, one layer per byte, a context
// per scanner channel (the channel switch as in item_rgb14.cpp).
#include <array>
#include <vector>

#include "cloud/laz/item_codec.hpp"

namespace spinhash::host::laz {
namespace {

constexpr uint32_t kChannels = 4;
constexpr uint32_t kByteSymbols = 256;

struct BytesContext {
  bool used = false;
  std::vector<uint8_t> last;
  std::vector<SymbolModel> models;

  void reset(const uint8_t* seed, size_t count) {
    if (models.size() != count) models.assign(count, SymbolModel(kByteSymbols));
    for (SymbolModel& m : models) m.reset();
    last.assign(seed, seed + count);
    used = true;
  }
};

class Byte14Item final : public LayeredItem {
 public:
  Byte14Item(uint16_t version, uint16_t count) : fixed_switch_(version >= 4), count_(count), dec_(count) {}
  size_t layer_count() const override { return count_; }

  void init(const uint8_t* first, const Layer* layers, uint32_t* context) override {
    present_.assign(count_, false);
    for (size_t i = 0; i < count_; ++i) {
      present_[i] = layers[i].size > 0;
      if (present_[i]) dec_[i].init(layers[i].begin, layers[i].begin + layers[i].size);
    }
    for (auto& c : contexts_) c.used = false;
    current_ = *context % kChannels;
    contexts_[current_].reset(first, count_);
  }

  void decode(uint8_t* out, uint32_t* context) override {
    uint8_t* last = contexts_[current_].last.data();
    const uint32_t wanted = *context % kChannels;
    if (wanted != current_) {
      current_ = wanted;
      BytesContext& next = contexts_[wanted];
      if (!next.used) {
        next.reset(last, count_);
        last = next.last.data();
      } else if (fixed_switch_) {
        last = next.last.data();
      }
    }
    BytesContext& c = contexts_[current_];
    for (size_t i = 0; i < count_; ++i) {
      if (present_[i]) last[i] = u8_fold(static_cast<int32_t>(last[i] + dec_[i].decode_symbol(c.models[i])));
      out[i] = last[i];
    }
  }

  size_t overrun() const override {
    size_t worst = 0;
    for (const ArithmeticDecoder& d : dec_) worst = std::max(worst, d.overrun());
    return worst;
  }

  // Extra bytes are not the pipeline's.
  bool pipeline_layer(size_t /*layer*/) const override { return false; }

 private:
  bool fixed_switch_;
  size_t count_;
  std::vector<ArithmeticDecoder> dec_;
  std::vector<bool> present_;
  std::array<BytesContext, kChannels> contexts_;
  uint32_t current_ = 0;
};

}  // namespace

std::unique_ptr<LayeredItem> make_byte14(uint16_t version, uint16_t count) {
  return std::make_unique<Byte14Item>(version, count);
}

}  // namespace spinhash::host::laz
