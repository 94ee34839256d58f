// GPSTIME11: the 8-byte GPS time of formats 1, 3, 4 and 5.
#include "cloud/laz/gps_time_codec.hpp"
#include "cloud/laz/integer_decompressor.hpp"
#include "cloud/laz/item_codec.hpp"

namespace spinhash::host::laz {
namespace {

class GpsTime11V2 final : public PointwiseItem {
 public:
  void init(const uint8_t* first) override { codec_.reset(get_u64(first)); }
  void decode(ArithmeticDecoder& dec, uint8_t* out) override { put_u64(out, codec_.decode(dec)); }

 private:
  GpsTimeDecoder codec_{false};
};

// Version 1: one sequence, multipliers up to kMultiMax - 3, a raw 64-bit
// escape.
constexpr int32_t kMultiMax = 512;
constexpr uint32_t kZeroDiffSymbols = 3;
constexpr int32_t kExtremeRuns = 3;

class GpsTime11V1 final : public PointwiseItem {
 public:
  void init(const uint8_t* first) override {
    last_diff_ = 0;
    extreme_ = 0;
    multi_.reset();
    zero_diff_.reset();
    ic_.reset();
    time_ = get_u64(first);
  }

  void decode(ArithmeticDecoder& dec, uint8_t* out) override {
    if (last_diff_ == 0) {
      const uint32_t code = dec.decode_symbol(zero_diff_);
      if (code == 1) {
        last_diff_ = ic_.decompress(dec, 0, 0);
        add(last_diff_);
      } else if (code == 2) {
        time_ = dec.read_int64();
      }
    } else {
      decode_multi(dec);
    }
    put_u64(out, time_);
  }

 private:
  void add(int32_t diff) { time_ += static_cast<uint64_t>(static_cast<int64_t>(diff)); }
  int32_t predict(int32_t multi) {
    return static_cast<int32_t>(static_cast<uint32_t>(static_cast<int64_t>(multi) * last_diff_));
  }
  void count_extreme(int32_t diff) {
    if (++extreme_ > kExtremeRuns) {
      last_diff_ = diff;
      extreme_ = 0;
    }
  }
  void decode_multi(ArithmeticDecoder& dec) {
    const int32_t multi = static_cast<int32_t>(dec.decode_symbol(multi_));
    if (multi >= kMultiMax - 2) {
      if (multi < kMultiMax - 1) time_ = dec.read_int64();
      return;
    }
    int32_t diff;
    if (multi == 1) {
      diff = ic_.decompress(dec, last_diff_, 1);
      last_diff_ = diff;
      extreme_ = 0;
    } else if (multi == 0) {
      diff = ic_.decompress(dec, last_diff_ / 4, 2);
      count_extreme(diff);
    } else if (multi < 10) {
      diff = ic_.decompress(dec, predict(multi), 3);
    } else if (multi < 50) {
      diff = ic_.decompress(dec, predict(multi), 4);
    } else {
      diff = ic_.decompress(dec, predict(multi), 5);
      if (multi == kMultiMax - 3) count_extreme(diff);
    }
    add(diff);
  }

  int32_t last_diff_ = 0, extreme_ = 0;
  uint64_t time_ = 0;
  SymbolModel multi_{kMultiMax}, zero_diff_{kZeroDiffSymbols};
  IntegerDecompressor ic_{32, 6};
};

}  // namespace

std::unique_ptr<PointwiseItem> make_gpstime11(uint16_t version) {
  if (version == 1) return std::make_unique<GpsTime11V1>();
  return std::make_unique<GpsTime11V2>();
}

}  // namespace spinhash::host::laz
