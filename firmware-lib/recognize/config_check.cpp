#include "recognize/config_check.hpp"

#include <cmath>

#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"

namespace spinhash {
namespace {

// One range check per kind of the field lists; functions, so that a field
// whose range is its type's whole range compiles without "comparison is
// always true".
bool in_range_MODE(Mode v, int lo, int hi) { return static_cast<int>(v) >= lo && static_cast<int>(v) <= hi; }
bool in_range_BOOL(bool, int, int) { return true; }
bool in_range_U32(uint32_t v, uint32_t lo, uint32_t hi) { return v >= lo && v <= hi; }
bool in_range_U64(uint64_t v, uint64_t lo, uint64_t hi) { return v >= lo && v <= hi; }
bool in_range_F32(float v, float lo, float hi) { return v >= lo && v <= hi; }  // false for NaN
bool in_range_VEC3D(const double (&)[3], int, int) { return true; }  // checked with has_viewpoint below

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
  // Each stage's fields, through `p`, the stage's member.
#define SPINHASH_CHECK_PARAM(kind, name, def, lo, hi, flag, why) ok = ok && in_range_##kind(p.name, lo, hi);
#define SPINHASH_CHECK_STAGE(id, Name, what)   \
  {                                            \
    const Name##Params& p = c.id;              \
    SPINHASH_PARAMS_##id(SPINHASH_CHECK_PARAM) \
  }
  SPINHASH_STAGES(SPINHASH_CHECK_STAGE)
#undef SPINHASH_CHECK_STAGE
#undef SPINHASH_CHECK_PARAM
  return ok && joint_rules_hold(c);
}

}  // namespace spinhash
