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
  int32_t decompress(ArithmeticDecoder& dec, int32_t pred, uint32_t context = 0);
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

}  // namespace spinhash::host::laz
