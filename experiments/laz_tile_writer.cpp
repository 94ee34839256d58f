#include "laz_tile_writer.hpp"

#include <array>
#include <cstring>
#include <fstream>
#include <memory>

#include "cloud/laz/arithmetic_decoder.hpp"
#include "cloud/laz/item_codec.hpp"

namespace spinhash::experiment {
namespace {

using host::laz::BitModel;
using host::laz::kAcMinLength;
using host::laz::kBitLengthShift;
using host::laz::kSymbolLengthShift;
using host::laz::Median5;
using host::laz::SymbolModel;

constexpr size_t kRecord = 20;
constexpr uint32_t kByteSymbols = 256;

// The range encoder the decoder mirrors (carry propagated in the output).
class Encoder {
 public:
  void encode_symbol(SymbolModel& m, uint32_t sym) {
    const uint32_t init_base = base_;
    if (sym == m.last_symbol_) {
      const uint32_t x = m.distribution_[sym] * (length_ >> kSymbolLengthShift);
      base_ += x;
      length_ -= x;
    } else {
      const uint32_t x = m.distribution_[sym] * (length_ >>= kSymbolLengthShift);
      base_ += x;
      length_ = m.distribution_[sym + 1] * length_ - x;
    }
    if (init_base > base_) carry();
    if (length_ < kAcMinLength) renormalise();
    ++m.symbol_count_[sym];
    if (--m.symbols_until_update_ == 0) m.update();
  }
  void encode_bit(BitModel& m, uint32_t bit) {
    const uint32_t x = m.bit_0_prob_ * (length_ >> kBitLengthShift);
    if (bit == 0) {
      length_ = x;
      ++m.bit_0_count_;
    } else {
      const uint32_t init_base = base_;
      base_ += x;
      length_ -= x;
      if (init_base > base_) carry();
    }
    if (length_ < kAcMinLength) renormalise();
    if (--m.bits_until_update_ == 0) m.update();
  }
  void write_bits(uint32_t bits, uint32_t sym) {
    if (bits > 19) {
      write_bits(16, sym & 0xFFFF);
      sym >>= 16;
      bits -= 16;
    }
    const uint32_t init_base = base_;
    base_ += sym * (length_ >>= bits);
    if (init_base > base_) carry();
    if (length_ < kAcMinLength) renormalise();
  }
  // Flushes the interval and the zero bytes the decoder reads ahead.
  std::vector<uint8_t> done() {
    const uint32_t init_base = base_;
    bool another = true;
    if (length_ > 2 * kAcMinLength) {
      base_ += kAcMinLength;
      length_ = kAcMinLength >> 1;
    } else {
      base_ += kAcMinLength >> 1;
      length_ = kAcMinLength >> 9;
      another = false;
    }
    if (init_base > base_) carry();
    renormalise();
    out_.push_back(0);
    out_.push_back(0);
    if (another) out_.push_back(0);
    return std::move(out_);
  }

 private:
  void carry() {
    for (size_t i = out_.size(); i-- > 0;) {
      if (out_[i] != 0xFF) {
        ++out_[i];
        return;
      }
      out_[i] = 0;
    }
  }
  void renormalise() {
    do {
      out_.push_back(static_cast<uint8_t>(base_ >> 24));
      base_ <<= 8;
    } while ((length_ <<= 8) < kAcMinLength);
  }

  uint32_t base_ = 0, length_ = 0xFFFFFFFFu;
  std::vector<uint8_t> out_;
};

class IntegerCompressor {
 public:
  IntegerCompressor(uint32_t bits, uint32_t contexts) : bits_(bits < 32 ? bits : 32) {
    for (uint32_t c = 0; c < contexts; ++c) bit_models_.emplace_back(bits_ + 1);
    for (uint32_t i = 1; i <= bits_; ++i) correctors_.emplace_back(i <= 8 ? 1u << i : 1u << 8);
  }
  void compress(Encoder& e, int32_t pred, int32_t real, uint32_t context = 0) {
    int64_t corr = static_cast<int64_t>(real) - pred;
    if (bits_ < 32) {
      const int64_t range = int64_t{1} << bits_, min = -(range / 2), max = min + range - 1;
      if (corr < min)
        corr += range;
      else if (corr > max)
        corr -= range;
    } else {
      corr = static_cast<int32_t>(static_cast<uint32_t>(corr));
    }
    write_corrector(e, corr, bit_models_[context]);
  }
  uint32_t k() const { return k_; }

 private:
  void write_corrector(Encoder& e, int64_t c, SymbolModel& bits_model) {
    uint64_t c1 = static_cast<uint64_t>(c <= 0 ? -c : c - 1);
    k_ = 0;
    while (c1) {
      c1 >>= 1;
      ++k_;
    }
    e.encode_symbol(bits_model, k_);
    if (k_ == 0) {
      e.encode_bit(corrector0_, static_cast<uint32_t>(c));
      return;
    }
    if (k_ >= 32) return;
    c = c < 0 ? c + ((int64_t{1} << k_) - 1) : c - 1;
    if (k_ <= 8) {
      e.encode_symbol(correctors_[k_ - 1], static_cast<uint32_t>(c));
    } else {
      const uint32_t low = k_ - 8;
      e.encode_symbol(correctors_[k_ - 1], static_cast<uint32_t>(c >> low));
      e.write_bits(low, static_cast<uint32_t>(c & ((int64_t{1} << low) - 1)));
    }
  }

  uint32_t bits_, k_ = 0;
  std::vector<SymbolModel> bit_models_, correctors_;
  BitModel corrector0_;
};

constexpr uint8_t kReturnMap[8][8] = {{15, 14, 13, 12, 11, 10, 9, 8},  {14, 0, 1, 3, 6, 10, 10, 9},
                                      {13, 1, 2, 4, 7, 11, 11, 10},    {12, 3, 4, 5, 8, 12, 12, 11},
                                      {11, 6, 7, 8, 9, 13, 13, 12},    {10, 10, 11, 12, 13, 14, 14, 13},
                                      {9, 10, 11, 12, 13, 14, 15, 14}, {8, 9, 10, 11, 12, 13, 14, 15}};

uint32_t even_capped(uint32_t k, uint32_t cap) { return k < cap ? (k & ~1u) : cap; }

// POINT10 version 2, the mirror of item_point10.cpp's decoder; one per chunk.
class Point10Writer {
 public:
  explicit Point10Writer(const uint8_t* first) {
    std::memcpy(last_.data(), first, kRecord);
    last_[12] = last_[13] = 0;
  }
  void write(Encoder& e, const uint8_t* p) {
    using host::laz::get_i32;
    using host::laz::get_u16;
    const uint32_t r = p[14] & 7u, n = (p[14] >> 3) & 7u, m = kReturnMap[n][r];
    const uint32_t level = n > r ? n - r : r - n;
    const uint16_t intensity = get_u16(p + 12);
    const uint32_t changed = ((last_[14] != p[14]) << 5) | ((last_intensity_[m] != intensity) << 4) |
                             ((last_[15] != p[15]) << 3) | ((last_[16] != p[16]) << 2) |
                             ((last_[17] != p[17]) << 1) | (get_u16(last_.data() + 18) != get_u16(p + 18));
    e.encode_symbol(changed_, changed);
    if (changed & 32u) e.encode_symbol(model(flags_, last_[14]), p[14]);
    if (changed & 16u) {
      intensity_.compress(e, last_intensity_[m], intensity, m < 3 ? m : 3);
      last_intensity_[m] = intensity;
    }
    if (changed & 8u) e.encode_symbol(model(classes_, last_[15]), p[15]);
    if (changed & 4u) e.encode_symbol(scan_angle_[(p[14] >> 6) & 1u], host::laz::u8_fold(p[16] - last_[16]));
    if (changed & 2u) e.encode_symbol(model(user_data_, last_[17]), p[17]);
    if (changed & 1u) source_.compress(e, get_u16(last_.data() + 18), get_u16(p + 18));
    const uint32_t single = n == 1 ? 1u : 0u;
    int32_t diff =
        static_cast<int32_t>(static_cast<uint32_t>(get_i32(p)) - static_cast<uint32_t>(get_i32(&last_[0])));
    dx_.compress(e, x_median_[m].get(), diff, single);
    x_median_[m].add(diff);
    diff = static_cast<int32_t>(static_cast<uint32_t>(get_i32(p + 4)) -
                                static_cast<uint32_t>(get_i32(&last_[4])));
    dy_.compress(e, y_median_[m].get(), diff, single + even_capped(dx_.k(), 20));
    y_median_[m].add(diff);
    const uint32_t k_bits = (dx_.k() + dy_.k()) / 2;
    dz_.compress(e, last_height_[level], get_i32(p + 8), single + even_capped(k_bits, 18));
    last_height_[level] = get_i32(p + 8);
    std::memcpy(last_.data(), p, kRecord);
  }

 private:
  static SymbolModel& model(std::array<std::unique_ptr<SymbolModel>, kByteSymbols>& models, uint8_t key) {
    if (!models[key]) models[key] = std::make_unique<SymbolModel>(kByteSymbols);
    return *models[key];
  }

  std::array<uint8_t, kRecord> last_{};
  uint16_t last_intensity_[16] = {};
  Median5 x_median_[16], y_median_[16];
  int32_t last_height_[8] = {};
  SymbolModel changed_{64};
  IntegerCompressor intensity_{16, 4}, source_{16, 1}, dx_{32, 2}, dy_{32, 22}, dz_{32, 20};
  SymbolModel scan_angle_[2] = {SymbolModel(kByteSymbols), SymbolModel(kByteSymbols)};
  std::array<std::unique_ptr<SymbolModel>, kByteSymbols> flags_, classes_, user_data_;
};

void put(std::vector<uint8_t>* b, size_t at, uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) (*b)[at + static_cast<size_t>(i)] = static_cast<uint8_t>(v >> (8 * i));
}
void put_double(std::vector<uint8_t>* b, size_t at, double d) {
  uint64_t u;
  std::memcpy(&u, &d, sizeof u);
  put(b, at, u, 8);
}

// LAS 1.2 header + the LASzip VLR (compressor 2, one POINT10 v2 item).
std::vector<uint8_t> header_bytes(const host::LasHeader& h, uint64_t count, uint32_t chunk_size) {
  constexpr size_t kHeader = 227, kVlrHead = 54, kVlrData = 34 + 6;
  std::vector<uint8_t> b(kHeader + kVlrHead + kVlrData, 0);
  std::memcpy(b.data(), "LASF", 4);
  b[24] = 1;
  b[25] = 2;
  put(&b, 94, kHeader, 2);
  put(&b, 96, b.size(), 4);
  put(&b, 100, 1, 4);
  b[104] = 0x80;  // format 0, compressed
  put(&b, 105, kRecord, 2);
  put(&b, 107, count, 4);
  for (int a = 0; a < 3; ++a) {
    put_double(&b, 131 + 8 * a, h.scale[a]);
    put_double(&b, 155 + 8 * a, h.offset[a]);
    put_double(&b, 179 + 16 * a, h.max[a]);
    put_double(&b, 187 + 16 * a, h.min[a]);
  }
  std::memcpy(&b[kHeader + 2], "laszip encoded", 14);
  put(&b, kHeader + 18, 22204, 2);
  put(&b, kHeader + 20, kVlrData, 2);
  const size_t d = kHeader + kVlrHead;
  put(&b, d, 2, 2);  // compressor: pointwise chunked
  b[d + 4] = 3;      // LASzip 3.4
  b[d + 5] = 4;
  put(&b, d + 12, chunk_size, 4);
  put(&b, d + 16, ~uint64_t{0}, 8);  // no special EVLRs
  put(&b, d + 24, ~uint64_t{0}, 8);
  put(&b, d + 32, 1, 2);
  put(&b, d + 34, 6, 2);  // POINT10
  put(&b, d + 36, kRecord, 2);
  put(&b, d + 38, 2, 2);  // version 2
  return b;
}

}  // namespace

bool write_format0_laz(const std::string& path, const host::LasHeader& h, const std::vector<uint8_t>& records,
                       uint32_t chunk_size, std::string* error) {
  const uint64_t count = records.size() / kRecord;
  std::vector<uint8_t> out = header_bytes(h, count, chunk_size);
  const size_t table_offset_at = out.size();
  out.resize(out.size() + 8);
  std::vector<uint32_t> chunk_bytes;
  for (uint64_t first = 0; first < count; first += chunk_size) {
    const uint64_t n = std::min<uint64_t>(chunk_size, count - first);
    const uint8_t* p = records.data() + first * kRecord;
    const size_t start = out.size();
    out.insert(out.end(), p, p + kRecord);
    Encoder e;
    Point10Writer w(p);
    for (uint64_t i = 1; i < n; ++i) w.write(e, p + i * kRecord);
    const std::vector<uint8_t> coded = e.done();
    out.insert(out.end(), coded.begin(), coded.end());
    chunk_bytes.push_back(static_cast<uint32_t>(out.size() - start));
  }
  put(&out, table_offset_at, out.size(), 8);
  std::vector<uint8_t> head(8, 0);
  put(&head, 4, chunk_bytes.size(), 4);
  out.insert(out.end(), head.begin(), head.end());
  Encoder e;
  IntegerCompressor ic(32, 2);
  for (size_t i = 0; i < chunk_bytes.size(); ++i)
    ic.compress(e, i ? static_cast<int32_t>(chunk_bytes[i - 1]) : 0, static_cast<int32_t>(chunk_bytes[i]), 1);
  const std::vector<uint8_t> table = e.done();
  out.insert(out.end(), table.begin(), table.end());
  std::ofstream f(path, std::ios::binary);
  if (!f.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()))) {
    if (error) *error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace spinhash::experiment
