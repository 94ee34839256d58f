#include "cloud/laz/gps_time_codec.hpp"

#include "cloud/cloud_error.hpp"

namespace spinhash::host::laz {
namespace {

// Alphabet sizes: multipliers kGpsMultiMinus .. kGpsMulti plus escapes.
constexpr uint32_t kMultiSymbolsV2 = kGpsMulti - kGpsMultiMinus + 6;
constexpr uint32_t kMultiSymbolsLayered = kGpsMulti - kGpsMultiMinus + 5;
constexpr uint32_t kZeroDiffSymbolsV2 = 6;
constexpr uint32_t kZeroDiffSymbolsLayered = 5;
constexpr uint32_t kSequenceMask = kGpsSequences - 1;

int32_t wrap_mul(int32_t a, int32_t b) {
  return static_cast<int32_t>(static_cast<uint32_t>(static_cast<int64_t>(a) * b));
}

}  // namespace

GpsTimeDecoder::GpsTimeDecoder(bool layered)
    : layered_(layered),
      code_full_(kGpsMulti - kGpsMultiMinus + (layered ? 1 : 2)),
      multi_(layered ? kMultiSymbolsLayered : kMultiSymbolsV2),
      zero_diff_(layered ? kZeroDiffSymbolsLayered : kZeroDiffSymbolsV2) {}

void GpsTimeDecoder::reset(uint64_t first_time_bits) {
  last_ = next_ = 0;
  for (uint32_t i = 0; i < kGpsSequences; ++i) time_[i] = diff_[i] = extreme_[i] = 0;
  time_[0] = first_time_bits;
  multi_.reset();
  zero_diff_.reset();
  ic_.reset();
}

void GpsTimeDecoder::decode_full(ArithmeticDecoder& dec) {
  next_ = (next_ + 1) & kSequenceMask;
  const int32_t high = ic_.decompress(dec, static_cast<int32_t>(time_[last_] >> 32), 8);
  time_[next_] = (static_cast<uint64_t>(static_cast<uint32_t>(high)) << 32) | dec.read_int();
  last_ = next_;
  diff_[last_] = 0;
  extreme_[last_] = 0;
}

void GpsTimeDecoder::count_extreme(int32_t diff) {
  if (++extreme_[last_] > kGpsExtremeRuns) {
    diff_[last_] = diff;
    extreme_[last_] = 0;
  }
}

bool GpsTimeDecoder::decode_zero_diff(ArithmeticDecoder& dec) {
  // Codes: v2 0 unchanged, 1 small, 2 full, >2 switch; layered one lower.
  const int32_t code = static_cast<int32_t>(dec.decode_symbol(zero_diff_)) + (layered_ ? 1 : 0);
  if (code == 1) {
    diff_[last_] = ic_.decompress(dec, 0, 0);
    time_[last_] += static_cast<uint64_t>(static_cast<int64_t>(diff_[last_]));
    extreme_[last_] = 0;
  } else if (code == 2) {
    decode_full(dec);
  } else if (code > 2) {
    last_ = (last_ + static_cast<uint32_t>(code) - 2) & kSequenceMask;
    return false;
  }
  return true;
}

bool GpsTimeDecoder::decode_multi(ArithmeticDecoder& dec) {
  int32_t multi = static_cast<int32_t>(dec.decode_symbol(multi_));
  const int32_t last_diff = diff_[last_];
  if (multi == 1) {
    time_[last_] += static_cast<uint64_t>(static_cast<int64_t>(ic_.decompress(dec, last_diff, 1)));
    extreme_[last_] = 0;
  } else if (multi < code_full_ - (layered_ ? 0 : 1)) {
    int32_t diff;
    if (multi == 0) {
      diff = ic_.decompress(dec, 0, 7);
      count_extreme(diff);
    } else if (multi < kGpsMulti) {
      diff = ic_.decompress(dec, wrap_mul(multi, last_diff), multi < 10 ? 2 : 3);
    } else if (multi == kGpsMulti) {
      diff = ic_.decompress(dec, wrap_mul(kGpsMulti, last_diff), 4);
      count_extreme(diff);
    } else {
      multi = kGpsMulti - multi;
      if (multi > kGpsMultiMinus) {
        diff = ic_.decompress(dec, wrap_mul(multi, last_diff), 5);
      } else {
        diff = ic_.decompress(dec, wrap_mul(kGpsMultiMinus, last_diff), 6);
        count_extreme(diff);
      }
    }
    time_[last_] += static_cast<uint64_t>(static_cast<int64_t>(diff));
  } else if (multi == code_full_) {
    decode_full(dec);
  } else if (multi > code_full_) {
    last_ = (last_ + static_cast<uint32_t>(multi - code_full_)) & kSequenceMask;
    return false;
  }
  return true;
}

uint64_t GpsTimeDecoder::decode(ArithmeticDecoder& dec) {
  for (int i = 0; i < kGpsMaxSwitches; ++i) {
    const bool done = diff_[last_] == 0 ? decode_zero_diff(dec) : decode_multi(dec);
    if (done) return time_[last_];
  }
  throw CloudError("LAZ: corrupt GPS time stream (it switches time sequence endlessly)");
}

}  // namespace spinhash::host::laz
