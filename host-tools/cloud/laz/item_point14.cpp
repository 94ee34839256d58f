// POINT14: the 30 bytes every format 6-10 record starts with, in nine
// layers (channel/returns/xy, z, class, flags, intensity, scan angle, user
// data, point source, GPS time), each with its own decoder, and four
// contexts, one per scanner channel.
#include <array>
#include <memory>

#include "cloud/laz/gps_time_codec.hpp"
#include "cloud/laz/integer_decompressor.hpp"
#include "cloud/laz/item_codec.hpp"

namespace spinhash::host::laz {
namespace {

constexpr size_t kPoint14Bytes = 30;
constexpr uint32_t kChannels = 4;
enum LayerIndex : size_t {
  kXY,
  kZ,
  kClass,
  kFlags,
  kIntensity,
  kScanAngle,
  kUserData,
  kSource,
  kTime,
  kLayers
};

constexpr uint32_t kChangedSymbols = 128;
constexpr uint32_t kChannelSymbols = 3;
constexpr uint32_t kReturnSymbols = 16;
constexpr uint32_t kGpsSameReturnSymbols = 13;
constexpr uint32_t kByteSymbols = 256;
constexpr uint32_t kFlagSymbols = 64;
constexpr uint32_t kPrevReturnContexts = 8;  // first/last x time changed
constexpr uint32_t kMedianContexts = 12;     // 6 return maps x time changed
constexpr uint32_t kLevels = 8;
constexpr uint32_t kKeyedModels = 64;

// The fields of a LAS 1.4 point record (format 6 layout) that the layers
// code, plus whether the last point's time changed.
struct Point14 {
  int32_t x = 0, y = 0, z = 0;
  uint16_t intensity = 0;
  uint8_t return_number = 0, returns = 0;
  uint8_t class_flags = 0, channel = 0, scan_direction = 0, edge = 0;
  uint8_t classification = 0, user_data = 0;
  int16_t scan_angle = 0;
  uint16_t source = 0;
  uint64_t time = 0;
  bool time_changed = false;
};

Point14 unpack(const uint8_t* p) {
  Point14 q;
  q.x = get_i32(p);
  q.y = get_i32(p + 4);
  q.z = get_i32(p + 8);
  q.intensity = get_u16(p + 12);
  q.return_number = p[14] & 0x0F;
  q.returns = p[14] >> 4;
  q.class_flags = p[15] & 0x0F;
  q.channel = (p[15] >> 4) & 3;
  q.scan_direction = (p[15] >> 6) & 1;
  q.edge = p[15] >> 7;
  q.classification = p[16];
  q.user_data = p[17];
  q.scan_angle = static_cast<int16_t>(get_u16(p + 18));
  q.source = get_u16(p + 20);
  q.time = get_u64(p + 22);
  return q;
}

void pack(const Point14& q, uint8_t* p) {
  put_i32(p, q.x);
  put_i32(p + 4, q.y);
  put_i32(p + 8, q.z);
  put_u16(p + 12, q.intensity);
  p[14] = static_cast<uint8_t>(q.return_number | (q.returns << 4));
  p[15] = static_cast<uint8_t>(q.class_flags | (q.channel << 4) | (q.scan_direction << 6) | (q.edge << 7));
  p[16] = q.classification;
  p[17] = q.user_data;
  put_u16(p + 18, static_cast<uint16_t>(q.scan_angle));
  put_u16(p + 20, q.source);
  put_u64(p + 22, q.time);
}

// Return contexts: the (number of returns, return number) pairs that matter
// get their own of six contexts (LAZ specification, LAS 1.4 points).
constexpr uint8_t kReturnMap6[16][16] = {
    {0, 1, 2, 3, 4, 5, 3, 4, 4, 5, 5, 5, 5, 5, 5, 5}, {1, 0, 1, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3},
    {2, 1, 2, 4, 4, 4, 4, 4, 4, 4, 4, 3, 3, 3, 3, 3}, {3, 3, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4}, {5, 3, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {3, 3, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4}, {4, 3, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4}, {5, 3, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4}, {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 4, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4, 4}, {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5}, {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5}};

uint32_t level_of(uint32_t n, uint32_t r) {
  const uint32_t d = n > r ? n - r : r - n;
  return d < kLevels - 1 ? d : kLevels - 1;
}
// Contexts of y and z: the (even) corrector bit count of x, or of x and y,
// capped; a single return adds one.
constexpr uint32_t kDyContextCap = 20, kDzContextCap = 18;

uint32_t even_capped(uint32_t k, uint32_t cap) { return k < cap ? (k & ~1u) : cap; }

// Models created when first needed (a fresh model equals a reset one).
class KeyedModels {
 public:
  explicit KeyedModels(uint32_t symbols) : symbols_(symbols) {}
  SymbolModel& at(size_t key) {
    auto& m = models_[key];
    if (!m) m = std::make_unique<SymbolModel>(symbols_);
    return *m;
  }
  void reset() {
    for (auto& m : models_)
      if (m) m->reset();
  }

 private:
  uint32_t symbols_;
  std::array<std::unique_ptr<SymbolModel>, kKeyedModels> models_;
};

struct ChannelContext {
  bool used = false;
  Point14 last;
  uint16_t last_intensity[kLevels] = {};
  Median5 x_median[kMedianContexts], y_median[kMedianContexts];
  int32_t last_z[kLevels] = {};
  std::array<SymbolModel, kPrevReturnContexts> changed{
      SymbolModel(kChangedSymbols), SymbolModel(kChangedSymbols), SymbolModel(kChangedSymbols),
      SymbolModel(kChangedSymbols), SymbolModel(kChangedSymbols), SymbolModel(kChangedSymbols),
      SymbolModel(kChangedSymbols), SymbolModel(kChangedSymbols)};
  SymbolModel channel{kChannelSymbols};
  KeyedModels returns{kReturnSymbols}, return_number{kReturnSymbols};
  SymbolModel return_gps_same{kGpsSameReturnSymbols};
  IntegerDecompressor dx{32, 2}, dy{32, 22}, dz{32, 20};
  KeyedModels classes{kByteSymbols}, flags{kFlagSymbols}, user_data{kByteSymbols};
  IntegerDecompressor intensity{16, 4}, scan_angle{16, 2}, source{16, 1};
  GpsTimeDecoder time{true};

  void reset(const Point14& seed) {
    for (SymbolModel& m : changed) m.reset();
    channel.reset();
    returns.reset();
    return_number.reset();
    return_gps_same.reset();
    dx.reset();
    dy.reset();
    for (uint32_t i = 0; i < kMedianContexts; ++i) {
      x_median[i].reset();
      y_median[i].reset();
    }
    dz.reset();
    for (uint32_t i = 0; i < kLevels; ++i) {
      last_z[i] = seed.z;
      last_intensity[i] = seed.intensity;
    }
    classes.reset();
    flags.reset();
    user_data.reset();
    intensity.reset();
    scan_angle.reset();
    source.reset();
    time.reset(seed.time);
    last = seed;
    last.time_changed = false;
    used = true;
  }
};

class Point14Item final : public LayeredItem {
 public:
  size_t layer_count() const override { return kLayers; }

  void init(const uint8_t* first, const Layer* layers, uint32_t* context) override {
    for (size_t i = 0; i < kLayers; ++i) {
      present_[i] = layers[i].size > 0;
      if (i == kXY || present_[i]) dec_[i].init(layers[i].begin, layers[i].begin + layers[i].size);
    }
    for (auto& c : contexts_)
      if (c) c->used = false;
    const Point14 seed = unpack(first);
    current_ = seed.channel;
    *context = current_;
    channel(current_).reset(seed);
  }

  void decode(uint8_t* out, uint32_t* context) override {
    ChannelContext* c = contexts_[current_].get();
    const uint32_t prev = previous_return_context(c->last);
    const uint32_t changed = dec_[kXY].decode_symbol(c->changed[prev]);
    if (changed & (1u << 6)) c = switch_channel(c, context);
    Point14& p = c->last;
    const bool time_changed = (changed & (1u << 4)) != 0;
    decode_returns(c, changed, time_changed);
    const uint32_t n = p.returns, r = p.return_number;
    const uint32_t m = kReturnMap6[n][r];
    const uint32_t level = level_of(n, r);
    const uint32_t cpr = (r == 1 ? 1u : 0u) + (r >= n ? 2u : 0u);
    decode_xyz(c, n, m, level, time_changed);
    decode_attributes(c, cpr, changed, time_changed);
    pack(p, out);
    p.time_changed = time_changed;
  }

  size_t overrun() const override {
    size_t worst = 0;
    for (const ArithmeticDecoder& d : dec_) worst = std::max(worst, d.overrun());
    return worst;
  }

  // The channel, returns and x y share the first layer; z, the class and
  // the class flags (withheld) have their own.
  bool pipeline_layer(size_t layer) const override {
    return layer == kXY || layer == kZ || layer == kClass || layer == kFlags;
  }

 private:
  static uint32_t previous_return_context(const Point14& last) {
    uint32_t lpr = last.return_number == 1 ? 1u : 0u;
    lpr += last.return_number >= last.returns ? 2u : 0u;
    return lpr + (last.time_changed ? 4u : 0u);
  }

  ChannelContext* switch_channel(ChannelContext* c, uint32_t* context) {
    const uint32_t diff = dec_[kXY].decode_symbol(c->channel);
    const uint32_t channel = (current_ + diff + 1) % kChannels;
    ChannelContext* next = &this->channel(channel);
    if (!next->used) next->reset(c->last);  // a new channel starts from the current point
    current_ = channel;
    *context = channel;
    next->last.channel = static_cast<uint8_t>(channel);
    return next;
  }

  void decode_returns(ChannelContext* c, uint32_t changed, bool time_changed) {
    Point14& p = c->last;
    const uint32_t last_n = p.returns, last_r = p.return_number;
    if (changed & (1u << 2)) p.returns = static_cast<uint8_t>(dec_[kXY].decode_symbol(c->returns.at(last_n)));
    switch (changed & 3u) {
      case 0: break;
      case 1: p.return_number = static_cast<uint8_t>((last_r + 1) % kReturnSymbols); break;
      case 2: p.return_number = static_cast<uint8_t>((last_r + kReturnSymbols - 1) % kReturnSymbols); break;
      default:
        if (time_changed) {
          p.return_number = static_cast<uint8_t>(dec_[kXY].decode_symbol(c->return_number.at(last_r)));
        } else {
          const uint32_t sym = dec_[kXY].decode_symbol(c->return_gps_same);
          p.return_number = static_cast<uint8_t>((last_r + sym + 2) % kReturnSymbols);
        }
    }
  }

  void decode_xyz(ChannelContext* c, uint32_t n, uint32_t m, uint32_t level, bool time_changed) {
    Point14& p = c->last;
    const uint32_t single = n == 1 ? 1u : 0u;
    const uint32_t mc = (m << 1) | (time_changed ? 1u : 0u);
    int32_t diff = c->dx.decompress(dec_[kXY], c->x_median[mc].get(), single);
    p.x = static_cast<int32_t>(static_cast<uint32_t>(p.x) + static_cast<uint32_t>(diff));
    c->x_median[mc].add(diff);
    diff = c->dy.decompress(dec_[kXY], c->y_median[mc].get(), single + even_capped(c->dx.k(), kDyContextCap));
    p.y = static_cast<int32_t>(static_cast<uint32_t>(p.y) + static_cast<uint32_t>(diff));
    c->y_median[mc].add(diff);
    if (present_[kZ]) {
      const uint32_t k_bits = (c->dx.k() + c->dy.k()) / 2;
      p.z = c->dz.decompress(dec_[kZ], c->last_z[level], single + even_capped(k_bits, kDzContextCap));
      c->last_z[level] = p.z;
    }
  }

  void decode_attributes(ChannelContext* c, uint32_t cpr, uint32_t changed, bool time_changed) {
    Point14& p = c->last;
    if (present_[kClass]) {
      const size_t key = ((p.classification & 0x1Fu) << 1) + (cpr == 3 ? 1u : 0u);
      p.classification = static_cast<uint8_t>(dec_[kClass].decode_symbol(c->classes.at(key)));
    }
    if (present_[kFlags]) {
      const size_t key = (p.edge << 5) | (p.scan_direction << 4) | p.class_flags;
      const uint32_t f = dec_[kFlags].decode_symbol(c->flags.at(key));
      p.edge = (f >> 5) & 1u;
      p.scan_direction = (f >> 4) & 1u;
      p.class_flags = f & 0x0Fu;
    }
    if (present_[kIntensity]) {
      const uint32_t ic = (cpr << 1) | (time_changed ? 1u : 0u);
      p.intensity =
          static_cast<uint16_t>(c->intensity.decompress(dec_[kIntensity], c->last_intensity[ic], cpr));
      c->last_intensity[ic] = p.intensity;
    }
    if (present_[kScanAngle] && (changed & (1u << 3)))
      p.scan_angle =
          static_cast<int16_t>(c->scan_angle.decompress(dec_[kScanAngle], p.scan_angle, time_changed));
    if (present_[kUserData])
      p.user_data = static_cast<uint8_t>(dec_[kUserData].decode_symbol(c->user_data.at(p.user_data / 4)));
    if (present_[kSource] && (changed & (1u << 5)))
      p.source = static_cast<uint16_t>(c->source.decompress(dec_[kSource], p.source));
    if (present_[kTime] && time_changed) p.time = c->time.decode(dec_[kTime]);
  }

  // A channel's models are created when the channel first appears (most
  // files have one): about half a megabyte each.
  ChannelContext& channel(uint32_t c) {
    if (!contexts_[c]) contexts_[c] = std::make_unique<ChannelContext>();
    return *contexts_[c];
  }

  ArithmeticDecoder dec_[kLayers];
  bool present_[kLayers] = {};
  std::array<std::unique_ptr<ChannelContext>, kChannels> contexts_;
  uint32_t current_ = 0;
};

}  // namespace

std::unique_ptr<LayeredItem> make_point14(uint16_t /*version*/) { return std::make_unique<Point14Item>(); }

}  // namespace spinhash::host::laz
