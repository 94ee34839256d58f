#include "recognize/config_check.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>

#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/stage_fields.h"

namespace spinhash {
namespace {

// One range check per kind of the top-level list; functions, so that a
// field whose range is its type's whole range compiles without "comparison
// is always true".
bool in_range_MODE(Mode v, int lo, int hi) { return static_cast<int>(v) >= lo && static_cast<int>(v) <= hi; }
bool in_range_BOOL(bool, int, int) { return true; }
bool in_range_U32(uint32_t v, uint32_t lo, uint32_t hi) { return v >= lo && v <= hi; }
bool in_range_U64(uint64_t v, uint64_t lo, uint64_t hi) { return v >= lo && v <= hi; }
[[maybe_unused]] bool in_range_F32(float v, float lo, float hi) {
  return v >= lo && v <= hi;
}  // false for NaN
bool in_range_VEC3D(const double (&)[3], int, int) { return true; }  // checked with has_viewpoint below

// The stages' fields are checked from tables (offset in the stage's struct,
// range), one loop per kind: a hundred fields' checks as data, not code (the
// core's image is small). A stage without fields of a kind has the
// terminator alone.
constexpr uint16_t kEndOfRows = 0xFFFFu;
struct F32Range {
  uint16_t offset;
  float lo, hi;
};
struct U32Range {
  uint16_t offset;
  uint32_t lo, hi;
};

bool floats_in_range(const void* stage, const F32Range* rows) {
  bool ok = true;
  for (; rows->offset != kEndOfRows; ++rows) {  // bounded by the table's terminator
    float v;
    std::memcpy(&v, static_cast<const char*>(stage) + rows->offset, sizeof v);
    ok = ok && v >= rows->lo && v <= rows->hi;  // false for NaN
  }
  return ok;
}

bool uints_in_range(const void* stage, const U32Range* rows) {
  bool ok = true;
  for (; rows->offset != kEndOfRows; ++rows) {
    uint32_t v;
    std::memcpy(&v, static_cast<const char*>(stage) + rows->offset, sizeof v);
    ok = ok && v >= rows->lo && v <= rows->hi;
  }
  return ok;
}

#define SPINHASH_F32_ROW_F32(P, name, lo, hi) {static_cast<uint16_t>(offsetof(P, name)), lo, hi},
#define SPINHASH_F32_ROW_U32(P, name, lo, hi)
#define SPINHASH_F32_ROW_BOOL(P, name, lo, hi)
#define SPINHASH_U32_ROW_U32(P, name, lo, hi) {static_cast<uint16_t>(offsetof(P, name)), lo, hi},
#define SPINHASH_U32_ROW_F32(P, name, lo, hi)
#define SPINHASH_U32_ROW_BOOL(P, name, lo, hi)
#define SPINHASH_F32_ROW(kind, name, def, lo, hi, flag, why) SPINHASH_F32_ROW_##kind(P, name, lo, hi)
#define SPINHASH_U32_ROW(kind, name, def, lo, hi, flag, why) SPINHASH_U32_ROW_##kind(P, name, lo, hi)
#define SPINHASH_STAGE_ROWS(id, Name, what)                                                          \
  namespace id##_rows {                                                                              \
    using P = Name##Params;                                                                          \
    static_assert(sizeof(P) < kEndOfRows, #Name "Params: offsets fit 16 bits");                      \
    constexpr F32Range kFloats[] = {SPINHASH_PARAMS_##id(SPINHASH_F32_ROW){kEndOfRows, 0.0f, 0.0f}}; \
    constexpr U32Range kUints[] = {SPINHASH_PARAMS_##id(SPINHASH_U32_ROW){kEndOfRows, 0u, 0u}};      \
  }
SPINHASH_STAGES(SPINHASH_STAGE_ROWS)
#undef SPINHASH_STAGE_ROWS
#undef SPINHASH_U32_ROW
#undef SPINHASH_F32_ROW

// The rules that join two fields.
bool joint_rules_hold(const RecognizerConfig& c) {
  return c.draws.delta_max >= c.draws.delta &&
         (!c.has_viewpoint ||
          (std::isfinite(c.viewpoint[0]) && std::isfinite(c.viewpoint[1]) && std::isfinite(c.viewpoint[2])));
}

}  // namespace

bool config_valid(const RecognizerConfig& c) {
  bool ok = true;
#define SPINHASH_CHECK_RANGE(kind, name, lo, hi, flag, help) ok = ok && in_range_##kind(c.name, lo, hi);
  SPINHASH_CONFIG_FIELDS(SPINHASH_CHECK_RANGE)
#undef SPINHASH_CHECK_RANGE
#define SPINHASH_CHECK_STAGE(id, Name, what) \
  ok = ok && floats_in_range(&c.id, id##_rows::kFloats) && uints_in_range(&c.id, id##_rows::kUints);
  SPINHASH_STAGES(SPINHASH_CHECK_STAGE)
#undef SPINHASH_CHECK_STAGE
  return ok && joint_rules_hold(c);
}

}  // namespace spinhash
