// BYTE: the extra bytes after the standard fields of formats 0-5, each byte
// its own context.
#include <vector>

#include "cloud/laz/integer_decompressor.hpp"
#include "cloud/laz/item_codec.hpp"

namespace spinhash::host::laz {
namespace {

constexpr uint32_t kByteSymbols = 256;

class ByteV2 final : public PointwiseItem {
 public:
  explicit ByteV2(uint16_t count) : last_(count), models_(count, SymbolModel(kByteSymbols)) {}
  void init(const uint8_t* first) override {
    for (SymbolModel& m : models_) m.reset();
    std::copy(first, first + last_.size(), last_.begin());
  }
  void decode(ArithmeticDecoder& dec, uint8_t* out) override {
    for (size_t i = 0; i < last_.size(); ++i) {
      out[i] = u8_fold(static_cast<int32_t>(last_[i] + dec.decode_symbol(models_[i])));
      last_[i] = out[i];
    }
  }

 private:
  std::vector<uint8_t> last_;
  std::vector<SymbolModel> models_;
};

class ByteV1 final : public PointwiseItem {
 public:
  explicit ByteV1(uint16_t count) : last_(count), ic_(8, count) {}
  void init(const uint8_t* first) override {
    ic_.reset();
    std::copy(first, first + last_.size(), last_.begin());
  }
  void decode(ArithmeticDecoder& dec, uint8_t* out) override {
    for (size_t i = 0; i < last_.size(); ++i) {
      out[i] = static_cast<uint8_t>(ic_.decompress(dec, last_[i], static_cast<uint32_t>(i)));
      last_[i] = out[i];
    }
  }

 private:
  std::vector<uint8_t> last_;
  IntegerDecompressor ic_;
};

}  // namespace

std::unique_ptr<PointwiseItem> make_byte(uint16_t version, uint16_t count) {
  if (version == 1) return std::make_unique<ByteV1>(count);
  return std::make_unique<ByteV2>(count);
}

}  // namespace spinhash::host::laz
