// LASzip's colour predictor (RGB12 v2, RGB14, RGBNIR14): which of the six
// colour bytes changed, each coded as a difference from the last, green and
// blue predicted from red's change.
#pragma once

#include <cstdint>

#include "cloud/laz/arithmetic_decoder.hpp"

namespace spinhash::host::laz {

constexpr uint32_t kRgbByteUsedSymbols = 128;
constexpr uint32_t kRgbDiffSymbols = 256;

class RgbDecoder {
 public:
  void reset();
  // Decodes the next r g b from last[0..3) into out[0..3).
  void decode(ArithmeticDecoder& dec, const uint16_t* last, uint16_t* out);

 private:
  SymbolModel byte_used_{kRgbByteUsedSymbols};
  SymbolModel diff_[6] = {SymbolModel(kRgbDiffSymbols), SymbolModel(kRgbDiffSymbols),
                          SymbolModel(kRgbDiffSymbols), SymbolModel(kRgbDiffSymbols),
                          SymbolModel(kRgbDiffSymbols), SymbolModel(kRgbDiffSymbols)};
};

}  // namespace spinhash::host::laz
