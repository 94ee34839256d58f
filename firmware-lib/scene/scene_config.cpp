// The validity of a SceneConfig and a StreamConfig: every field within its
// range of scene_fields.h (the one place the ranges are checked), plus the
// rules that join two fields.
#include <cmath>

#include "scene/scene_window.hpp"
#include "scene/window_lattice.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/scene_fields.h"
#include "spinhash/scene_stream.hpp"

namespace spinhash {
namespace {

// One range check per kind of the lists; functions, so that a field whose
// range is its type's whole range compiles without "comparison is always
// true".
bool in_range_U32(uint32_t v, uint32_t lo, uint32_t hi) { return v >= lo && v <= hi; }
bool in_range_U64(uint64_t v, uint64_t lo, uint64_t hi) { return v >= lo && v <= hi; }
bool in_range_F32(float v, float lo, float hi) { return v >= lo && v <= hi; }  // false for NaN
bool in_range_BOOL(bool, int, int) { return true; }
bool in_range_VEC3D(const double (&)[3], int, int) { return true; }  // checked with origin_given below

bool multiple_of(float v, float cell) {
  const float k = v / cell;
  return std::fabs(k - std::round(k)) < 1e-4f;
}

// A window's objects come whole and a cut one never passes the size gates:
// a cut object owned by the core spans twice the object margin, which no
// footprint within max_length x max_width reaches (its diagonal). The
// terrain sees at least as far.
bool objects_whole(const SceneConfig& c) {
  return 2.0f * c.object_margin >= std::hypot(c.max_length, c.max_width) &&
         c.object_margin <= c.window_margin;
}

// The layer gap is a whole number of column bins, within a column.
bool layer_gap_fits(const SceneConfig& c) {
  const float bins = std::round(c.layer_gap / c.column_bin);
  return multiple_of(c.layer_gap, c.column_bin) && bins >= 1.0f &&
         bins < static_cast<float>(kSegmentColumnBins);
}

}  // namespace

bool scene_config_valid(const SceneConfig& c) noexcept {
  bool ok = true;
#define SPINHASH_CHECK_RANGE(kind, name, lo, hi, flag, help) ok = ok && in_range_##kind(c.name, lo, hi);
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_CHECK_RANGE)
#undef SPINHASH_CHECK_RANGE
  return ok && required_workspace_bytes(scene_object_config(c)) > 0 &&
         multiple_of(c.window_core, c.terrain_cell) && multiple_of(c.window_core, c.segment_cell) &&
         multiple_of(c.window_margin, c.terrain_cell) && objects_whole(c) &&
         c.terrain_window >= c.terrain_cell && c.terrain_dh_max >= c.terrain_dh0 &&
         (c.terrain_noise_gap == 0.0f || c.terrain_noise_gap >= c.terrain_low_band) &&
         c.max_length >= c.min_length && c.max_width >= c.min_width && c.max_height >= c.min_height &&
         layer_gap_fits(c);
}

bool stream_config_valid(const StreamConfig& c) noexcept {
  bool ok = true;
#define SPINHASH_CHECK_RANGE(kind, name, lo, hi, flag, help) ok = ok && in_range_##kind(c.name, lo, hi);
  SPINHASH_STREAM_CONFIG_FIELDS(SPINHASH_CHECK_RANGE)
#undef SPINHASH_CHECK_RANGE
  return ok && scene_config_valid(c.scene) && (!c.origin_given || finite_xyz(c.origin)) &&
         c.swath_min < c.swath_max && c.own_min < c.own_max && c.own_min >= c.swath_min &&
         c.own_max <= c.swath_max;
}

}  // namespace spinhash
