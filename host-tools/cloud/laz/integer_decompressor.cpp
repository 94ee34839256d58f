#include "cloud/laz/integer_decompressor.hpp"

#include <limits>

namespace spinhash::host::laz {

IntegerDecompressor::IntegerDecompressor(uint32_t bits, uint32_t contexts, uint32_t bits_high)
    : bits_high_(bits_high) {
  if (bits > 0 && bits < kMaxCorrectorBits) {
    corr_bits_ = bits;
    corr_range_ = 1u << bits;
    corr_min_ = -static_cast<int32_t>(corr_range_ / 2);
  } else {
    corr_bits_ = kMaxCorrectorBits;
    corr_range_ = 0;
    corr_min_ = std::numeric_limits<int32_t>::min();
  }
  bit_models_.resize(contexts);
  correctors_.resize(corr_bits_);
}

void IntegerDecompressor::reset() {
  k_ = 0;
  for (auto& m : bit_models_)
    if (m) m->reset();
  corrector0_.reset();
  for (auto& m : correctors_)
    if (m) m->reset();
}

SymbolModel& IntegerDecompressor::new_bits_model(uint32_t context) {
  auto& m = bit_models_[context];
  m = std::make_unique<SymbolModel>(corr_bits_ + 1);
  return *m;
}

SymbolModel& IntegerDecompressor::new_corrector(uint32_t k) {
  auto& m = correctors_[k - 1];
  m = std::make_unique<SymbolModel>(k <= bits_high_ ? 1u << k : 1u << bits_high_);
  return *m;
}

int32_t IntegerDecompressor::read_corrector(ArithmeticDecoder& dec, SymbolModel& bits_model) {
  k_ = dec.decode_symbol(bits_model);
  if (k_ == 0) return static_cast<int32_t>(dec.decode_bit(corrector0_));
  if (k_ >= kMaxCorrectorBits) return corr_min_;
  int64_t c;
  if (k_ <= bits_high_) {
    c = dec.decode_symbol(corrector(k_));
  } else {
    const uint32_t low_bits = k_ - bits_high_;
    c = dec.decode_symbol(corrector(k_));
    c = (c << low_bits) | dec.read_bits(low_bits);
  }
  // The k-bit value maps onto [-(2^k - 1), -2^(k-1)] and [2^(k-1), 2^k].
  const int64_t half = int64_t{1} << (k_ - 1);
  c = c >= half ? c + 1 : c - ((int64_t{1} << k_) - 1);
  return static_cast<int32_t>(c);
}

int32_t IntegerDecompressor::decompress(ArithmeticDecoder& dec, int32_t pred, uint32_t context) {
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

}  // namespace spinhash::host::laz
