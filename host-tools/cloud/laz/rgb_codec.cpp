#include "cloud/laz/rgb_codec.hpp"

#include "cloud/laz/item_codec.hpp"

namespace spinhash::host::laz {
namespace {

int32_t lo(uint16_t v) { return v & 0xFF; }
int32_t hi(uint16_t v) { return v >> 8; }

}  // namespace

void RgbDecoder::reset() {
  byte_used_.reset();
  for (SymbolModel& m : diff_) m.reset();
}

void RgbDecoder::decode(ArithmeticDecoder& dec, const uint16_t* last, uint16_t* out) {
  const uint32_t sym = dec.decode_symbol(byte_used_);
  auto corr = [&](int i) { return static_cast<int32_t>(dec.decode_symbol(diff_[i])); };
  int32_t r_lo = (sym & 1u) ? u8_fold(corr(0) + lo(last[0])) : lo(last[0]);
  int32_t r_hi = (sym & 2u) ? u8_fold(corr(1) + hi(last[0])) : hi(last[0]);
  out[0] = static_cast<uint16_t>(r_lo | (r_hi << 8));
  if ((sym & 64u) == 0) {  // grey: green and blue equal red
    out[1] = out[2] = out[0];
    return;
  }
  int32_t diff = r_lo - lo(last[0]);
  const int32_t g_lo = (sym & 4u) ? u8_fold(corr(2) + u8_clamp(diff + lo(last[1]))) : lo(last[1]);
  int32_t b_lo = lo(last[2]);
  if (sym & 16u) {
    diff = (diff + (g_lo - lo(last[1]))) / 2;
    b_lo = u8_fold(corr(4) + u8_clamp(diff + lo(last[2])));
  }
  diff = r_hi - hi(last[0]);
  const int32_t g_hi = (sym & 8u) ? u8_fold(corr(3) + u8_clamp(diff + hi(last[1]))) : hi(last[1]);
  int32_t b_hi = hi(last[2]);
  if (sym & 32u) {
    diff = (diff + (g_hi - hi(last[1]))) / 2;
    b_hi = u8_fold(corr(5) + u8_clamp(diff + hi(last[2])));
  }
  out[1] = static_cast<uint16_t>(g_lo | (g_hi << 8));
  out[2] = static_cast<uint16_t>(b_lo | (b_hi << 8));
}

}  // namespace spinhash::host::laz
