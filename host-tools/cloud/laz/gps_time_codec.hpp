// The GPS-time predictor LASzip uses from item version 2 on (GPSTIME11 v2
// and, with a smaller alphabet, POINT14's time layer): up to four time
// sequences, each predicting the next 64-bit time from its last integer
// difference times a small multiplier, with escapes for a full 64-bit time
// and for switching sequence.
#pragma once

#include <cstdint>

#include "cloud/laz/integer_decompressor.hpp"

namespace spinhash::host::laz {

constexpr int32_t kGpsMulti = 500;
constexpr int32_t kGpsMultiMinus = -10;
constexpr uint32_t kGpsSequences = 4;
constexpr int32_t kGpsExtremeRuns = 3;  // extreme multipliers this often reset the difference
// A corrupt stream could switch sequence forever; a valid one switches once.
constexpr int kGpsMaxSwitches = 8;

class GpsTimeDecoder {
 public:
  // layered: POINT14's alphabet (0-diff 5 symbols, codes shifted by one).
  explicit GpsTimeDecoder(bool layered);
  void reset(uint64_t first_time_bits);
  uint64_t decode(ArithmeticDecoder& dec);  // the next time's bits

 private:
  bool decode_zero_diff(ArithmeticDecoder& dec);  // true: decoded, false: switched
  bool decode_multi(ArithmeticDecoder& dec);
  void decode_full(ArithmeticDecoder& dec);
  void count_extreme(int32_t diff);

  bool layered_;
  int32_t code_full_;  // the multi code of a full 64-bit time
  uint32_t last_ = 0, next_ = 0;
  uint64_t time_[kGpsSequences] = {};
  int32_t diff_[kGpsSequences] = {};
  int32_t extreme_[kGpsSequences] = {};
  SymbolModel multi_, zero_diff_;
  IntegerDecompressor ic_{32, 9};
};

}  // namespace spinhash::host::laz
