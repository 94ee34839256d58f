// Layout of the stream's golden vectors (tests/golden/): a short flight-line
// strip that record_golden writes (record_golden_stream.cpp) and
// test_golden_stream.cpp pushes through SceneStream on every target. See
// tests/golden/README.md.
#pragma once
#include <cstdint>

#include "golden/golden_format.hpp"
#include "spinhash/scene_stream.hpp"

namespace spinhash {
namespace golden {

// golden_stream.i16: x y z per point, little-endian int16 in 1/256 m from
// kStreamOrigin, in scan order. A power-of-two unit decodes exactly (no
// rounding anywhere), and int16 spans +-128 m, enough for the strip.
constexpr uint32_t kStreamBytesPerCoordinate = 2;
constexpr double kStreamUnitsPerMetre = 256.0;
constexpr double kStreamOrigin[3] = {512384.0, 5412352.0, 312.0};  // UTM-like, multiples of the core

// One coordinate of golden_stream.i16, georeferenced: the same double on every IEEE target.
inline double decode_stream(const uint8_t* le, int axis) {
  const auto u = static_cast<uint16_t>(le[0] | (le[1] << 8));
  return static_cast<double>(static_cast<int16_t>(u)) / kStreamUnitsPerMetre + kStreamOrigin[axis];
}

// The stream's chunk in the "4 kB chunks" run: 4 096 bytes of xyz doubles.
constexpr uint32_t kStreamChunkPoints = 4096 / (3 * sizeof(double));

struct GoldenObject {
  int64_t row;  // the owning window
  uint32_t col;
  uint32_t kind;  // ObjectKind
  uint32_t points;
  int32_t model;  // first model, -1 without a ranking
  float score;    // its score (0 without a ranking)
  bool confident;
  double center[3];  // georeferenced
};

struct GoldenStreamStats {
  uint64_t points_pushed;
  uint64_t windows;
  uint64_t objects_reported;
  uint64_t objects_not_owned;
};

// The one stream setting used to record and to check: 32 m cores (rows at
// x = 0, 32, 64, 96 from the origin, columns split at y = 0) so that a
// 104 m strip crosses several windows; the golden recognizer setting
// (golden_config, BRAN) for every candidate; capacities of the strip.
constexpr float kStreamCore = 32.0f;
constexpr uint32_t kStreamCapacity = 1u << 16;  // points: the strip holds fewer

inline StreamConfig golden_stream_config() {
  StreamConfig c;
  c.scene.recognizer = golden_config(Mode::kBran);
  c.scene.window_core = kStreamCore;
  c.scene.max_tile_points = kStreamCapacity;
  c.origin_given = true;
  for (int i = 0; i < 3; ++i) c.origin[i] = kStreamOrigin[i];
  c.heading_deg = 0.0f;  // along +x: cos and sin exact, no libm in the frame
  c.swath_min = c.own_min = -kStreamCore;
  c.swath_max = c.own_max = kStreamCore;
  c.max_lag = 4.0f;  // the points come sorted along track
  c.max_buffered_points = kStreamCapacity;
  return c;
}

}  // namespace golden
}  // namespace spinhash
