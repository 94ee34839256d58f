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

}  // namespace spinhash::host::laz
