// LASzip's integer corrector: an integer is coded as a prediction plus a
// correction, the correction by its bit length k (a symbol per context) and
// then its value within that length (a symbol for the high bits, raw bits
// below). k of the last correction is exposed: the point codecs pick their
// next contexts by it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "cloud/laz/arithmetic_decoder.hpp"

namespace spinhash::host::laz {

constexpr uint32_t kCorrectorBitsHigh = 8;  // bits above this are raw
constexpr uint32_t kMaxCorrectorBits = 32;

class IntegerDecompressor {
 public:
  IntegerDecompressor(uint32_t bits, uint32_t contexts, uint32_t bits_high = kCorrectorBitsHigh);
  void reset();  // the models back to their start (a new chunk)
  // Inline: x y z of every point call it.
  int32_t decompress(ArithmeticDecoder& dec, int32_t pred, uint32_t context = 0) {
    const int32_t corr = read_corrector(dec, bits_model(context));
    // Wrap-around arithmetic in the corrector's range (two's complement).
    int64_t real = static_cast<int64_t>(pred) + corr;
    if (corr_range_ != 0) {
      if (real < 0)
        real += corr_range_;
      else if (real >= static_cast<int64_t>(corr_range_))
        real -= corr_range_;
    }
    return static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(real)));
  }
  uint32_t k() const { return k_; }

 private:
  int32_t read_corrector(ArithmeticDecoder& dec, SymbolModel& bits_model);

  uint32_t bits_high_;
  uint32_t corr_bits_;
  uint32_t corr_range_;  // 0: the full 32-bit range
  int32_t corr_min_;
  uint32_t k_ = 0;
  // Models are created on first use (a fresh model equals a reset one): a
  // 32-bit corrector has 32 models of up to 256 symbols, few of them used,
  // and building them all would dominate the decoding of small files.
  SymbolModel& bits_model(uint32_t context) {
    SymbolModel* m = bit_models_[context].get();
    return m != nullptr ? *m : new_bits_model(context);
  }
  SymbolModel& corrector(uint32_t k) {
    SymbolModel* m = correctors_[k - 1].get();
    return m != nullptr ? *m : new_corrector(k);
  }
  SymbolModel& new_bits_model(uint32_t context);
  SymbolModel& new_corrector(uint32_t k);

  std::vector<std::unique_ptr<SymbolModel>> bit_models_;  // one per context: k
  BitModel corrector0_;                                   // k == 0: the correction is 0 or 1
  std::vector<std::unique_ptr<SymbolModel>> correctors_;  // [k - 1]: the value's high bits
};

inline int32_t IntegerDecompressor::read_corrector(ArithmeticDecoder& dec, SymbolModel& bits_model) {
  const uint32_t k = k_ = dec.decode_symbol(bits_model);
  if (k == 0) return static_cast<int32_t>(dec.decode_bit(corrector0_));
  if (k >= kMaxCorrectorBits) return corr_min_;
  int64_t c = dec.decode_symbol(corrector(k));
  if (k > bits_high_) {
    const uint32_t low_bits = k - bits_high_;
    c = (c << low_bits) | dec.read_bits(low_bits);
  }
  // The k-bit value maps onto [-(2^k - 1), -2^(k-1)] and [2^(k-1), 2^k].
  const int64_t half = int64_t{1} << (k - 1);
  c = c >= half ? c + 1 : c - ((int64_t{1} << k) - 1);
  return static_cast<int32_t>(c);
}

}  // namespace spinhash::host::laz
