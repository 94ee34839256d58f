// The LASzip entropy decoder, written from the LAZ format's description: a
// 32-bit range decoder (Said's "fast arithmetic coding" as LASzip uses it)
// with adaptive multi-symbol and bit models. Bytes come from a span, refilled
// by an optional feed (a chunk streamed from a file). Reading past the data
// yields zeros and is counted, never undefined: a corrupt stream decodes to
// garbage that the caller detects, it cannot crash.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace spinhash::host::laz {

constexpr uint32_t kAcMinLength = 0x01000000u;  // renormalise below 2^24
constexpr uint32_t kAcMaxLength = 0xFFFFFFFFu;
constexpr uint32_t kBitLengthShift = 13;  // bit-model probability precision
constexpr uint32_t kBitMaxCount = 1u << kBitLengthShift;
constexpr uint32_t kSymbolLengthShift = 15;  // symbol-model precision
constexpr uint32_t kSymbolMaxCount = 1u << kSymbolLengthShift;
constexpr uint32_t kMaxModelSymbols = 1u << 11;  // LASzip's largest alphabet
// Every symbol model has a decoder table, at least this many entries a
// symbol (up to kTableMaxBits): most lookups then land on a single symbol
// and skip the search. The search is exact, so the sizes change only the
// work (docs/decisions/023).
constexpr uint32_t kTableEntriesPerSymbol = 4;
constexpr uint32_t kTableMinBits = 3, kTableMaxBits = 10;
constexpr uint32_t kBitModelMaxCycle = 64;
constexpr uint32_t kReadBitsDirect = 19;  // wider raw reads are split in two

// An adaptive model of `symbols` symbols (2 .. kMaxModelSymbols).
class SymbolModel {
 public:
  explicit SymbolModel(uint32_t symbols);
  void reset();   // back to the equiprobable start of a chunk
  void update();  // recompute the distribution from the counts

  // The equiprobable start, computed once per alphabet size and copied by
  // reset(): every chunk of a LAZ file resets every model it uses.
  struct Start {
    uint32_t total_count = 0;
    std::vector<uint32_t> distribution;
    std::vector<uint16_t> decoder_table;
  };

  uint32_t symbols_;
  uint32_t last_symbol_;
  uint32_t table_size_ = 0, table_shift_ = 0;
  uint32_t total_count_ = 0, update_cycle_ = 0, symbols_until_update_ = 0;
  std::vector<uint32_t> distribution_, symbol_count_;
  // [t]: the last symbol whose distribution lies below t << table_shift_;
  // table_size_ + 2 entries.
  std::vector<uint16_t> decoder_table_;
  const Start* start_ = nullptr;

 private:
  void compute_start();
};

class BitModel {
 public:
  BitModel() { reset(); }
  void reset();
  void update();

  uint32_t bit_0_count_ = 1, bit_count_ = 2, bit_0_prob_ = 0;
  uint32_t update_cycle_ = 0, bits_until_update_ = 0;
};

// Hands the decoder more bytes when its span runs out; false at the end.
class ByteFeed {
 public:
  virtual ~ByteFeed() = default;
  virtual bool refill(const uint8_t** begin, const uint8_t** end) = 0;
};

class ArithmeticDecoder {
 public:
  // Starts decoding at `begin` (the first 4 bytes prime the value).
  void init(const uint8_t* begin, const uint8_t* end, ByteFeed* feed = nullptr);
  uint32_t decode_symbol(SymbolModel& m);
  uint32_t decode_bit(BitModel& m);
  uint32_t read_bits(uint32_t bits) {  // 1 .. 32 raw bits
    if (bits > kReadBitsDirect) return read_bits_split(bits);
    const uint32_t length = length_ >> bits;
    const uint32_t sym = value_ / length;
    value_ -= length * sym;
    length_ = length;
    if (length_ < kAcMinLength) renormalise();
    return sym;
  }
  uint32_t read_short() { return read_bits(16); }
  uint32_t read_int();
  uint64_t read_int64();
  // Bytes asked for beyond the data (zeros were supplied).
  size_t overrun() const { return overrun_; }
  // Takes `n` raw bytes from the stream before init (the chunk's first
  // point); false when the data ends first.
  bool take_raw(uint8_t* out, size_t n);
  // Points the decoder at bytes without priming it (take_raw, then start).
  void attach(const uint8_t* begin, const uint8_t* end, ByteFeed* feed);
  void start();

 private:
  uint8_t next_byte() { return p_ < end_ ? *p_++ : next_byte_slow(); }
  uint8_t next_byte_slow();
  uint32_t read_bits_split(uint32_t bits);
  void renormalise() {
    do {
      value_ = (value_ << 8) | next_byte();
    } while ((length_ <<= 8) < kAcMinLength);
  }

  const uint8_t* p_ = nullptr;
  const uint8_t* end_ = nullptr;
  ByteFeed* feed_ = nullptr;
  uint32_t value_ = 0, length_ = kAcMaxLength;
  size_t overrun_ = 0;
};

// The hot paths, inline: a point decodes a dozen symbols or more.
inline uint32_t ArithmeticDecoder::decode_symbol(SymbolModel& m) {
  // The state in locals: the count stores below could alias the members.
  const uint32_t length = length_ >> kSymbolLengthShift, value = value_;
  const uint32_t dv = value / length;
  // A corrupt stream can put the value past the interval: clamp the index.
  const uint32_t t = std::min(dv >> m.table_shift_, m.table_size_);
  const uint32_t* dist = m.distribution_.data();
  const uint16_t* table = m.decoder_table_.data();
  uint32_t sym = table[t];
  uint32_t n = table[t + 1] + 1u;
  while (n > sym + 1) {  // binary search in the table's bracket (masks, not branches)
    const uint32_t k = (sym + n) >> 1;
    const uint32_t above = 0u - static_cast<uint32_t>(dist[k] > dv);
    n = (k & above) | (n & ~above);
    sym = (sym & above) | (k & ~above);
  }
  const uint32_t x = dist[sym] * length;
  const uint32_t y = sym != m.last_symbol_ ? dist[sym + 1] * length : length_;
  value_ = value - x;
  length_ = y - x;
  if (length_ < kAcMinLength) renormalise();
  ++m.symbol_count_[sym];
  if (--m.symbols_until_update_ == 0) m.update();
  return sym;
}

inline uint32_t ArithmeticDecoder::decode_bit(BitModel& m) {
  const uint32_t x = m.bit_0_prob_ * (length_ >> kBitLengthShift);
  const uint32_t sym = value_ >= x ? 1u : 0u;
  if (sym == 0) {
    length_ = x;
    ++m.bit_0_count_;
  } else {
    value_ -= x;
    length_ -= x;
  }
  if (length_ < kAcMinLength) renormalise();
  if (--m.bits_until_update_ == 0) m.update();
  return sym;
}

}  // namespace spinhash::host::laz
