#include "cloud/laz/arithmetic_decoder.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>

namespace spinhash::host::laz {
namespace {

constexpr uint32_t kShortBits = 16;

}  // namespace

SymbolModel::SymbolModel(uint32_t symbols)
    : symbols_(std::clamp(symbols, 2u, kMaxModelSymbols)), last_symbol_(symbols_ - 1) {
  uint32_t table_bits = kTableMinBits;
  while (table_bits < kTableMaxBits && (1u << table_bits) < kTableEntriesPerSymbol * symbols_) ++table_bits;
  table_size_ = 1u << table_bits;
  table_shift_ = kSymbolLengthShift - table_bits;
  decoder_table_.assign(table_size_ + 2, 0);
  distribution_.assign(symbols_, 0);
  symbol_count_.assign(symbols_, 0);
  // The starts by alphabet size, shared by all models (and threads) and never freed.
  static std::mutex mutex;
  static std::map<uint32_t, std::unique_ptr<Start>> starts;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto& start = starts[symbols_];
    if (!start) {
      compute_start();
      start = std::make_unique<Start>(Start{total_count_, distribution_, decoder_table_});
    }
    start_ = start.get();
  }
  reset();
}

void SymbolModel::compute_start() {
  total_count_ = 0;
  update_cycle_ = symbols_;
  std::fill(symbol_count_.begin(), symbol_count_.end(), 1u);
  update();
}

void SymbolModel::reset() {
  total_count_ = start_->total_count;
  distribution_ = start_->distribution;
  decoder_table_ = start_->decoder_table;
  std::fill(symbol_count_.begin(), symbol_count_.end(), 1u);
  symbols_until_update_ = update_cycle_ = (symbols_ + 6) >> 1;
}

void SymbolModel::update() {
  // Halve the counts when the total would pass the precision.
  if ((total_count_ += update_cycle_) > kSymbolMaxCount) {
    total_count_ = 0;
    for (uint32_t& c : symbol_count_) total_count_ += (c = (c + 1) >> 1);
  }
  const uint32_t scale = 0x80000000u / total_count_;
  // Members in locals: the stores below could alias them.
  const uint32_t symbols = symbols_, shift = table_shift_, table_size = table_size_;
  uint32_t* dist = distribution_.data();
  const uint32_t* counts = symbol_count_.data();
  uint16_t* table = decoder_table_.data();
  uint32_t sum = 0, s = 0;
  for (uint32_t k = 0; k < symbols; ++k) {
    dist[k] = (scale * sum) >> (31 - kSymbolLengthShift);
    sum += counts[k];
    const uint32_t w = dist[k] >> shift;
    while (s < w) table[++s] = static_cast<uint16_t>(k - 1);
  }
  table[0] = 0;
  while (s <= table_size) table[++s] = static_cast<uint16_t>(symbols - 1);
  update_cycle_ = (5 * update_cycle_) >> 2;
  const uint32_t max_cycle = (symbols_ + 6) << 3;
  if (update_cycle_ > max_cycle) update_cycle_ = max_cycle;
  symbols_until_update_ = update_cycle_;
}

void BitModel::reset() {
  bit_0_count_ = 1;
  bit_count_ = 2;
  bit_0_prob_ = 1u << (kBitLengthShift - 1);
  update_cycle_ = bits_until_update_ = 4;
}

void BitModel::update() {
  if ((bit_count_ += update_cycle_) > kBitMaxCount) {
    bit_count_ = (bit_count_ + 1) >> 1;
    bit_0_count_ = (bit_0_count_ + 1) >> 1;
    if (bit_0_count_ == bit_count_) ++bit_count_;
  }
  const uint32_t scale = 0x80000000u / bit_count_;
  bit_0_prob_ = (bit_0_count_ * scale) >> (31 - kBitLengthShift);
  update_cycle_ = (5 * update_cycle_) >> 2;
  if (update_cycle_ > kBitModelMaxCycle) update_cycle_ = kBitModelMaxCycle;
  bits_until_update_ = update_cycle_;
}

void ArithmeticDecoder::attach(const uint8_t* begin, const uint8_t* end, ByteFeed* feed) {
  p_ = begin;
  end_ = end;
  feed_ = feed;
  overrun_ = 0;
}

void ArithmeticDecoder::init(const uint8_t* begin, const uint8_t* end, ByteFeed* feed) {
  attach(begin, end, feed);
  start();
}

void ArithmeticDecoder::start() {
  length_ = kAcMaxLength;
  value_ = 0;
  for (int i = 0; i < 4; ++i) value_ = (value_ << 8) | next_byte();
}

bool ArithmeticDecoder::take_raw(uint8_t* out, size_t n) {
  while (n > 0) {
    if (p_ == end_ && !(feed_ && feed_->refill(&p_, &end_))) return false;
    const size_t k = std::min(n, static_cast<size_t>(end_ - p_));
    std::memcpy(out, p_, k);
    p_ += k;
    out += k;
    n -= k;
  }
  return true;
}

uint8_t ArithmeticDecoder::next_byte_slow() {
  if (feed_ && feed_->refill(&p_, &end_) && p_ < end_) return *p_++;
  ++overrun_;
  return 0;
}

uint32_t ArithmeticDecoder::read_bits_split(uint32_t bits) {
  const uint32_t low = read_bits(kShortBits);
  const uint32_t high = read_bits(bits - kShortBits);
  return (high << kShortBits) | low;
}

uint32_t ArithmeticDecoder::read_int() {
  const uint32_t low = read_short();
  const uint32_t high = read_short();
  return (high << kShortBits) | low;
}

uint64_t ArithmeticDecoder::read_int64() {
  const uint64_t low = read_int();
  const uint64_t high = read_int();
  return (high << 32) | low;
}

}  // namespace spinhash::host::laz
