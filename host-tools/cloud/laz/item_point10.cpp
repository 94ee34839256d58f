// POINT10: the 20 bytes every format 0-5 record starts with (x y z,
// intensity, return/flags byte, class, scan angle rank, user data, point
// source id). Version 1 predicts x and y from the median of the last three
// differences; version 2 from streaming medians per return context and z
// from the last height per return level.
#include <algorithm>
#include <array>
#include <cstring>
#include <memory>

#include "cloud/laz/integer_decompressor.hpp"
#include "cloud/laz/item_codec.hpp"

namespace spinhash::host::laz {
namespace {

constexpr size_t kPoint10Bytes = 20;
constexpr size_t kXAt = 0, kYAt = 4, kZAt = 8, kIntensityAt = 12, kFlagsAt = 14, kClassAt = 15;
constexpr size_t kScanAngleAt = 16, kUserDataAt = 17, kSourceAt = 18;
constexpr uint32_t kByteSymbols = 256;
constexpr uint32_t kChangedSymbols = 64;
constexpr uint32_t kReturnContexts = 16;  // v2: the return map's contexts
constexpr uint32_t kLevels = 8;           // v2: |n - r|

// Lazily created models keyed by the last value of a byte (LASzip creates
// them when first needed; a fresh model equals a reset one).
class ByteModels {
 public:
  SymbolModel& at(uint8_t last) {
    auto& m = models_[last];
    if (!m) m = std::make_unique<SymbolModel>(kByteSymbols);
    return *m;
  }
  void reset() {
    for (auto& m : models_)
      if (m) m->reset();
  }

 private:
  std::array<std::unique_ptr<SymbolModel>, kByteSymbols> models_;
};

uint32_t return_number(const uint8_t* p) { return p[kFlagsAt] & 7u; }
uint32_t returns_of_pulse(const uint8_t* p) { return (p[kFlagsAt] >> 3) & 7u; }
uint32_t scan_direction(const uint8_t* p) { return (p[kFlagsAt] >> 6) & 1u; }

// Version 2's return map: the (number of returns, return number) pairs a
// correct file uses get contexts 0-14, the rest share the others.
constexpr uint8_t kReturnMap[8][8] = {{15, 14, 13, 12, 11, 10, 9, 8},  {14, 0, 1, 3, 6, 10, 10, 9},
                                      {13, 1, 2, 4, 7, 11, 11, 10},    {12, 3, 4, 5, 8, 12, 12, 11},
                                      {11, 6, 7, 8, 9, 13, 13, 12},    {10, 10, 11, 12, 13, 14, 14, 13},
                                      {9, 10, 11, 12, 13, 14, 15, 14}, {8, 9, 10, 11, 12, 13, 14, 15}};

// Contexts of y and z: the (even) corrector bit count of x, or of x and y,
// capped; a single return adds one. Intensity: the first three return maps.
constexpr uint32_t kDyContextCap = 20, kDzContextCap = 18, kIntensityContexts = 3;
// Version 1 uses the bit counts as they are, capped; a small one picks the
// scan angle's context.
constexpr uint32_t kV1ContextCap = 19, kV1SmallK = 3;
constexpr int kV1Diffs = 3;  // the last differences of x and y kept

uint32_t even_capped(uint32_t k, uint32_t cap) { return k < cap ? (k & ~1u) : cap; }

class Point10V2 final : public PointwiseItem {
 public:
  void init(const uint8_t* first) override {
    for (uint32_t i = 0; i < kReturnContexts; ++i) {
      x_median_[i].reset();
      y_median_[i].reset();
      last_intensity_[i] = 0;
    }
    last_height_.fill(0);
    changed_.reset();
    intensity_.reset();
    scan_angle_[0].reset();
    scan_angle_[1].reset();
    source_.reset();
    flags_.reset();
    classes_.reset();
    user_data_.reset();
    dx_.reset();
    dy_.reset();
    dz_.reset();
    std::copy(first, first + kPoint10Bytes, last_.begin());
    last_[kIntensityAt] = last_[kIntensityAt + 1] = 0;  // v2 predicts intensity from zero
  }

  void decode(ArithmeticDecoder& dec, uint8_t* out) override {
    uint8_t* l = last_.data();
    const uint32_t changed = dec.decode_symbol(changed_);
    if (changed != 0) decode_attributes(dec, changed);
    const uint32_t r = return_number(l), n = returns_of_pulse(l);
    const uint32_t m = kReturnMap[n][r];
    const uint32_t level = n > r ? n - r : r - n;
    if (changed != 0 && (changed & 16u) == 0) put_u16(l + kIntensityAt, last_intensity_[m]);
    if (changed != 0 && (changed & 16u) != 0) {
      const uint16_t v = static_cast<uint16_t>(
          intensity_.decompress(dec, last_intensity_[m], std::min(m, kIntensityContexts)));
      put_u16(l + kIntensityAt, v);
      last_intensity_[m] = v;
    }
    if (changed != 0) decode_after_intensity(dec, changed);
    const uint32_t single = n == 1 ? 1u : 0u;
    int32_t diff = dx_.decompress(dec, x_median_[m].get(), single);
    put_i32(l + kXAt,
            static_cast<int32_t>(static_cast<uint32_t>(get_i32(l + kXAt)) + static_cast<uint32_t>(diff)));
    x_median_[m].add(diff);
    diff = dy_.decompress(dec, y_median_[m].get(), single + even_capped(dx_.k(), kDyContextCap));
    put_i32(l + kYAt,
            static_cast<int32_t>(static_cast<uint32_t>(get_i32(l + kYAt)) + static_cast<uint32_t>(diff)));
    y_median_[m].add(diff);
    const uint32_t k_bits = (dx_.k() + dy_.k()) / 2;
    const int32_t z = dz_.decompress(dec, last_height_[level], single + even_capped(k_bits, kDzContextCap));
    put_i32(l + kZAt, z);
    last_height_[level] = z;
    std::memcpy(out, last_.data(), kPoint10Bytes);  // inline: a fixed size
  }

 private:
  // The flags byte comes first: the return context of the intensity needs it.
  void decode_attributes(ArithmeticDecoder& dec, uint32_t changed) {
    if (changed & 32u) last_[kFlagsAt] = static_cast<uint8_t>(dec.decode_symbol(flags_.at(last_[kFlagsAt])));
  }
  void decode_after_intensity(ArithmeticDecoder& dec, uint32_t changed) {
    uint8_t* l = last_.data();
    if (changed & 8u) l[kClassAt] = static_cast<uint8_t>(dec.decode_symbol(classes_.at(l[kClassAt])));
    if (changed & 4u) {
      const int32_t v = static_cast<int32_t>(dec.decode_symbol(scan_angle_[scan_direction(l)]));
      l[kScanAngleAt] = u8_fold(v + l[kScanAngleAt]);
    }
    if (changed & 2u) l[kUserDataAt] = static_cast<uint8_t>(dec.decode_symbol(user_data_.at(l[kUserDataAt])));
    if (changed & 1u)
      put_u16(l + kSourceAt, static_cast<uint16_t>(source_.decompress(dec, get_u16(l + kSourceAt))));
  }

  std::array<uint8_t, kPoint10Bytes> last_{};
  Median5 x_median_[kReturnContexts], y_median_[kReturnContexts];
  uint16_t last_intensity_[kReturnContexts] = {};
  std::array<int32_t, kLevels> last_height_{};
  SymbolModel changed_{kChangedSymbols};
  IntegerDecompressor intensity_{16, 4};
  SymbolModel scan_angle_[2] = {SymbolModel(kByteSymbols), SymbolModel(kByteSymbols)};
  IntegerDecompressor source_{16, 1};
  ByteModels flags_, classes_, user_data_;
  IntegerDecompressor dx_{32, 2}, dy_{32, 22}, dz_{32, 20};
};

int32_t median3(const int32_t* v) {
  if (v[0] < v[1]) return v[1] < v[2] ? v[1] : (v[0] < v[2] ? v[2] : v[0]);
  return v[0] < v[2] ? v[0] : (v[1] < v[2] ? v[2] : v[1]);
}

class Point10V1 final : public PointwiseItem {
 public:
  void init(const uint8_t* first) override {
    for (int i = 0; i < kV1Diffs; ++i) last_dx_[i] = last_dy_[i] = 0;
    next_ = 0;
    dx_.reset();
    dy_.reset();
    dz_.reset();
    intensity_.reset();
    scan_angle_.reset();
    source_.reset();
    changed_.reset();
    flags_.reset();
    classes_.reset();
    user_data_.reset();
    std::copy(first, first + kPoint10Bytes, last_.begin());
  }

  void decode(ArithmeticDecoder& dec, uint8_t* out) override {
    const uint8_t* l = last_.data();
    std::memcpy(out, last_.data(), kPoint10Bytes);
    const int32_t dx = dx_.decompress(dec, median3(last_dx_));
    put_i32(out + kXAt,
            static_cast<int32_t>(static_cast<uint32_t>(get_i32(l + kXAt)) + static_cast<uint32_t>(dx)));
    uint32_t k_bits = dx_.k();
    const int32_t dy = dy_.decompress(dec, median3(last_dy_), std::min(k_bits, kV1ContextCap));
    put_i32(out + kYAt,
            static_cast<int32_t>(static_cast<uint32_t>(get_i32(l + kYAt)) + static_cast<uint32_t>(dy)));
    k_bits = (k_bits + dy_.k()) / 2;
    put_i32(out + kZAt, dz_.decompress(dec, get_i32(l + kZAt), std::min(k_bits, kV1ContextCap)));
    const uint32_t changed = dec.decode_symbol(changed_);
    if (changed != 0) decode_attributes(dec, changed, k_bits, out);
    last_dx_[next_] = dx;
    last_dy_[next_] = dy;
    next_ = next_ == kV1Diffs - 1 ? 0 : next_ + 1;
    std::memcpy(last_.data(), out, kPoint10Bytes);
  }

 private:
  void decode_attributes(ArithmeticDecoder& dec, uint32_t changed, uint32_t k_bits, uint8_t* out) {
    const uint8_t* l = last_.data();
    if (changed & 32u)
      put_u16(out + kIntensityAt,
              static_cast<uint16_t>(intensity_.decompress(dec, get_u16(l + kIntensityAt))));
    if (changed & 16u) out[kFlagsAt] = static_cast<uint8_t>(dec.decode_symbol(flags_.at(l[kFlagsAt])));
    if (changed & 8u) out[kClassAt] = static_cast<uint8_t>(dec.decode_symbol(classes_.at(l[kClassAt])));
    if (changed & 4u)
      out[kScanAngleAt] =
          static_cast<uint8_t>(scan_angle_.decompress(dec, l[kScanAngleAt], k_bits < kV1SmallK ? 1 : 0));
    if (changed & 2u)
      out[kUserDataAt] = static_cast<uint8_t>(dec.decode_symbol(user_data_.at(l[kUserDataAt])));
    if (changed & 1u)
      put_u16(out + kSourceAt, static_cast<uint16_t>(source_.decompress(dec, get_u16(l + kSourceAt))));
  }

  std::array<uint8_t, kPoint10Bytes> last_{};
  int32_t last_dx_[kV1Diffs] = {}, last_dy_[kV1Diffs] = {};
  int next_ = 0;
  IntegerDecompressor dx_{32, 1}, dy_{32, 20}, dz_{32, 20};
  IntegerDecompressor intensity_{16, 1}, scan_angle_{8, 2}, source_{16, 1};
  SymbolModel changed_{kChangedSymbols};
  ByteModels flags_, classes_, user_data_;
};

}  // namespace

std::unique_ptr<PointwiseItem> make_point10(uint16_t version) {
  if (version == 1) return std::make_unique<Point10V1>();
  return std::make_unique<Point10V2>();
}

}  // namespace spinhash::host::laz
