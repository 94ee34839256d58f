#include "c_api/config_bridge.hpp"

#include "spinhash/config_fields.h"
#include "spinhash/stage_fields.h"

namespace spinhash {
namespace {

// One conversion per kind of the field lists.
void to_c(Mode in, int32_t* out) { *out = static_cast<int32_t>(in); }
void to_c(bool in, uint32_t* out) { *out = in ? 1u : 0u; }
void to_c(uint32_t in, uint32_t* out) { *out = in; }
void to_c(uint64_t in, uint64_t* out) { *out = in; }
void to_c(float in, float* out) { *out = in; }
void to_c(const double (&in)[3], double (*out)[3]) {
  for (int a = 0; a < 3; ++a) (*out)[a] = in[a];
}
void from_c(int32_t in, Mode* out) { *out = static_cast<Mode>(in); }
void from_c(uint32_t in, bool* out) { *out = in != 0u; }
void from_c(uint32_t in, uint32_t* out) { *out = in; }
void from_c(uint64_t in, uint64_t* out) { *out = in; }
void from_c(float in, float* out) { *out = in; }
void from_c(const double (&in)[3], double (*out)[3]) {
  for (int a = 0; a < 3; ++a) (*out)[a] = in[a];
}

// Stats: counters of any unsigned width widen to the C member.
template <typename C, typename T>
void stat_to_c(T in, C* out) {
  *out = static_cast<C>(in);
}
void stat_to_c(bool in, uint32_t* out) { *out = in ? 1u : 0u; }

}  // namespace

void to_c_config(const RecognizerConfig& in, spinhash_config* out) noexcept {
#define SPINHASH_TO_C(kind, name, lo, hi, flag, help) to_c(in.name, &out->name);
  SPINHASH_CONFIG_FIELDS(SPINHASH_TO_C)
#undef SPINHASH_TO_C
#define SPINHASH_PARAM_TO_C(kind, name, def, lo, hi, flag, why) to_c(from.name, &to.name);
#define SPINHASH_STAGE_TO_C(id, Name, what)   \
  {                                           \
    const Name##Params& from = in.id;         \
    spinhash_##id##_params& to = out->id;     \
    SPINHASH_PARAMS_##id(SPINHASH_PARAM_TO_C) \
  }
  SPINHASH_STAGES(SPINHASH_STAGE_TO_C)
#undef SPINHASH_STAGE_TO_C
#undef SPINHASH_PARAM_TO_C
}

bool from_c_config(const spinhash_config& in, RecognizerConfig* out) noexcept {
  if (in.mode != SPINHASH_MODE_BRAN && in.mode != SPINHASH_MODE_SRAN && in.mode != SPINHASH_MODE_SIND)
    return false;
#define SPINHASH_FROM_C(kind, name, lo, hi, flag, help) from_c(in.name, &out->name);
  SPINHASH_CONFIG_FIELDS(SPINHASH_FROM_C)
#undef SPINHASH_FROM_C
#define SPINHASH_PARAM_FROM_C(kind, name, def, lo, hi, flag, why) from_c(from.name, &to.name);
#define SPINHASH_STAGE_FROM_C(id, Name, what)   \
  {                                             \
    const spinhash_##id##_params& from = in.id; \
    Name##Params& to = out->id;                 \
    SPINHASH_PARAMS_##id(SPINHASH_PARAM_FROM_C) \
  }
  SPINHASH_STAGES(SPINHASH_STAGE_FROM_C)
#undef SPINHASH_STAGE_FROM_C
#undef SPINHASH_PARAM_FROM_C
  return true;
}

void to_c_stats(const RecognitionStats& in, spinhash_stats* out) noexcept {
#define SPINHASH_STATS_TO_C(kind, name, member, json) stat_to_c(in.member, &out->name);
  SPINHASH_STATS_FIELDS(SPINHASH_STATS_TO_C)
#undef SPINHASH_STATS_TO_C
}

}  // namespace spinhash
