// The field lists of spinhash/config_fields.h, spinhash/stage_fields.h and
// spinhash/scene_fields.h against the C++ structs they mirror: same fields,
// same types, the stages' defaults (at compile time), every recognizer field
// through the C struct and back with a value that is not its default, and
// every field's range checked by the core.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "c_api/config_bridge.hpp"
#include "recognize/config_check.hpp"
#include "recognize/stages.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"
#include "spinhash/scene_fields.h"
#include "spinhash/scene_stream.hpp"
#include "spinhash/stage_fields.h"

using namespace spinhash;

namespace {

// --- Counting an aggregate's members: the largest N for which T{x1..xN}
// compiles, with x convertible to any member type (an array member takes
// one initializer per element by brace elision).
struct AnyField {
  template <typename T>
  constexpr operator T() const noexcept {
    return T{};
  }
};

template <typename T, typename Seq, typename = void>
struct BraceInitializable : std::false_type {};
template <typename T, size_t... I>
struct BraceInitializable<T, std::index_sequence<I...>, std::void_t<decltype(T{(void(I), AnyField{})...})>>
    : std::true_type {};

template <typename T, size_t N = 0>
constexpr size_t member_count() {
  if constexpr (N > 256 || !BraceInitializable<T, std::make_index_sequence<N + 1>>::value)
    return N;
  else
    return member_count<T, N + 1>();
}

constexpr bool starts_with(const char* s, const char* prefix) {
  while (*prefix != '\0')
    if (*s++ != *prefix++) return false;
  return true;
}

// --- What the lists say.
constexpr size_t width_MODE = 1, width_BOOL = 1, width_U32 = 1, width_U64 = 1, width_F32 = 1, width_VEC3D = 3;
constexpr size_t listed_config_initializers() {
  size_t n = 1;  // the StageParams base: one initializer
#define SPINHASH_COUNT(kind, name, lo, hi, flag, help) n += width_##kind;
  SPINHASH_CONFIG_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}
constexpr size_t listed_stages() {
  size_t n = 0;
#define SPINHASH_COUNT(id, Name, what) ++n;
  SPINHASH_STAGES(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}
// Statistics whose member lies in `block` ("" for RecognitionStats' own).
constexpr bool in_block(const char* member, const char* block) {
  if (*block == '\0') {
    for (; *member != '\0'; ++member)
      if (*member == '.') return false;
    return true;
  }
  return starts_with(member, block);
}
constexpr size_t listed_stats(const char* block) {
  size_t n = 0;
#define SPINHASH_COUNT(kind, name, member, json) n += in_block(#member, block) ? 1u : 0u;
  SPINHASH_STATS_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}

static_assert(member_count<RecognizerConfig>() == listed_config_initializers(),
              "RecognizerConfig and SPINHASH_CONFIG_FIELDS (config_fields.h) list different fields");
static_assert(member_count<StageParams>() == listed_stages(),
              "StageParams and SPINHASH_STAGES (stage_fields.h) list different stages");
static_assert(member_count<ExtractStats>() == listed_stats("extract."),
              "ExtractStats and the extract.* entries of SPINHASH_STATS_FIELDS differ");
static_assert(member_count<GroundStats>() == listed_stats("ground."), "GroundStats and ground.* differ");
static_assert(member_count<CandidatesStats>() == listed_stats("candidates."),
              "CandidatesStats and candidates.* differ");
static_assert(member_count<DrawsStats>() == listed_stats("draws."), "DrawsStats and draws.* differ");
static_assert(member_count<TransferStats>() == listed_stats("transfer."),
              "TransferStats and transfer.* differ");
static_assert(member_count<RefineStats>() == listed_stats("refine."), "RefineStats and refine.* differ");
static_assert(member_count<ConfidenceStats>() == listed_stats("confidence."),
              "ConfidenceStats and confidence.* differ");
static_assert(member_count<CarryStats>() == listed_stats("carry."), "CarryStats and carry.* differ");
static_assert(member_count<CascadeStats>() == listed_stats("cascade."), "CascadeStats and cascade.* differ");
static_assert(member_count<RecognitionStats>() == listed_stats("") + 9u,
              "RecognitionStats and SPINHASH_STATS_FIELDS (config_fields.h) list different fields");

// Each stage's struct has exactly its list's fields, of the list's types,
// with the list's defaults, the defaults within the ranges; a stage with an
// `enabled` field has it first.
using CppType_MODE = Mode;
using CppType_BOOL = bool;
using CppType_U32 = uint32_t;
using CppType_U64 = uint64_t;
using CppType_F32 = float;
using CppType_VEC3D = double[3];

constexpr bool in_range(bool, int, int) { return true; }
constexpr bool in_range(uint32_t v, uint32_t lo, uint32_t hi) { return v >= lo && v <= hi; }
constexpr bool in_range(float v, float lo, float hi) { return v >= lo && v <= hi; }
constexpr bool same_name(const char* a, const char* b) {
  while (*a != '\0' && *a == *b) ++a, ++b;
  return *a == *b;
}

#define SPINHASH_PARAM_CHECKS(kind, name, def, lo, hi, flag, why)                          \
  static_assert(std::is_same<decltype(Params::name), CppType_##kind>::value,               \
                #name ": another type in its Params struct than in stage_fields.h");       \
  static_assert(Params{}.name == (def), #name ": another default than in stage_fields.h"); \
  static_assert(in_range(Params{}.name, lo, hi), #name ": the default is outside its range");
#define SPINHASH_COUNT_PARAM(kind, name, def, lo, hi, flag, why) +1
#define SPINHASH_ENABLED_AT(kind, name, def, lo, hi, flag, why) \
  ok = ok && (at++ == 0 || !same_name(#name, "enabled"));
#define SPINHASH_STAGE_CHECKS(id, Name, what)                                                   \
  namespace stage_##id {                                                                        \
    using Params = Name##Params;                                                                \
    static_assert(member_count<Params>() == 0 SPINHASH_PARAMS_##id(SPINHASH_COUNT_PARAM),       \
                  #Name "Params and SPINHASH_PARAMS_" #id " list different fields");            \
    static_assert(std::is_same<decltype(StageParams::id), Params>::value, "StageParams::" #id); \
    SPINHASH_PARAMS_##id(SPINHASH_PARAM_CHECKS) constexpr bool enabled_first() {                \
      int at = 0;                                                                               \
      bool ok = true;                                                                           \
      SPINHASH_PARAMS_##id(SPINHASH_ENABLED_AT) return ok;                                      \
    }                                                                                           \
    static_assert(enabled_first(), #Name "Params: `enabled` must be the first field");          \
  }
SPINHASH_STAGES(SPINHASH_STAGE_CHECKS)
#undef SPINHASH_STAGE_CHECKS
#undef SPINHASH_ENABLED_AT
#undef SPINHASH_COUNT_PARAM
#undef SPINHASH_PARAM_CHECKS

// --- Types: each kind's C++ type.
#define SPINHASH_SAME_TYPE(kind, name, lo, hi, flag, help)                             \
  static_assert(std::is_same<decltype(RecognizerConfig::name), CppType_##kind>::value, \
                #name ": another type in RecognizerConfig than in config_fields.h");
SPINHASH_CONFIG_FIELDS(SPINHASH_SAME_TYPE)
#undef SPINHASH_SAME_TYPE

template <typename T>
constexpr bool stat_fits(const char* kind) {
  if (starts_with(kind, "F32")) return std::is_same<T, float>::value;
  return starts_with(kind, "BOOL") ? std::is_same<T, bool>::value
                                   : std::is_unsigned<T>::value && !std::is_same<T, bool>::value &&
                                         sizeof(T) <= (starts_with(kind, "U32") ? 4u : 8u);
}
#define SPINHASH_STAT_TYPE(kind, name, member, json)                                     \
  static_assert(stat_fits<std::remove_cv_t<decltype(RecognitionStats{}.member)>>(#kind), \
                #member ": another type in RecognitionStats than in config_fields.h");
SPINHASH_STATS_FIELDS(SPINHASH_STAT_TYPE)
#undef SPINHASH_STAT_TYPE

// --- A value other than v for each kind (the k-th field gets its own).
Mode changed(Mode v, int) {
  return v == Mode::kSind ? Mode::kBran : static_cast<Mode>(static_cast<int>(v) + 1);
}
bool changed(bool v, int) { return !v; }
uint32_t changed(uint32_t v, int k) { return v + 7u + static_cast<uint32_t>(k); }
uint64_t changed(uint64_t v, int k) { return v + 0x100000000ull + static_cast<uint64_t>(k); }
float changed(float v, int k) { return v + 1.25f + static_cast<float>(k); }
void change(double (&v)[3], int k) {
  for (int a = 0; a < 3; ++a) v[a] += 1000.5 * (a + 1) + k;
}
template <typename T>
void change(T& v, int k) {
  v = changed(v, k);
}

bool same(Mode a, int32_t c) { return static_cast<int32_t>(a) == c; }
bool same(bool a, uint32_t c) { return c == (a ? 1u : 0u); }
bool same(uint32_t a, uint32_t c) { return a == c; }
bool same(uint64_t a, uint64_t c) { return a == c; }
bool same(float a, float c) { return std::memcmp(&a, &c, sizeof a) == 0; }
bool same(const double (&a)[3], const double (&c)[3]) { return std::memcmp(a, c, sizeof a) == 0; }

}  // namespace

TEST_CASE("config fields: every field survives C++ -> C -> C++ with a non-default value") {
  const RecognizerConfig defaults;
  RecognizerConfig edited;
  int k = 0;
#define SPINHASH_EDIT(kind, name, lo, hi, flag, help) change(edited.name, k++);
  SPINHASH_CONFIG_FIELDS(SPINHASH_EDIT)
#undef SPINHASH_EDIT
#define SPINHASH_EDIT_PARAM(kind, name, def, lo, hi, flag, why) change(p.name, k++);
#define SPINHASH_EDIT_STAGE(id, Name, what)   \
  {                                           \
    Name##Params& p = edited.id;              \
    SPINHASH_PARAMS_##id(SPINHASH_EDIT_PARAM) \
  }
  SPINHASH_STAGES(SPINHASH_EDIT_STAGE)
#undef SPINHASH_EDIT_STAGE
#undef SPINHASH_EDIT_PARAM

  spinhash_config c, c_defaults;
  std::memset(&c, 0xA5, sizeof c);
  to_c_config(edited, &c);
  to_c_config(defaults, &c_defaults);
  RecognizerConfig back;  // defaults: a field the bridge skips keeps its default and differs
  REQUIRE(from_c_config(c, &back));
#define SPINHASH_ROUND_TRIP(kind, name, lo, hi, flag, help) \
  {                                                         \
    INFO("field " #name);                                   \
    CHECK_FALSE(same(edited.name, c_defaults.name));        \
    CHECK(same(edited.name, c.name));                       \
    CHECK(same(back.name, c.name));                         \
  }
  SPINHASH_CONFIG_FIELDS(SPINHASH_ROUND_TRIP)
#undef SPINHASH_ROUND_TRIP
#define SPINHASH_PARAM_ROUND_TRIP(kind, name, def, lo, hi, flag, why) \
  {                                                                   \
    INFO("field " #name);                                             \
    CHECK_FALSE(same(mine.name, c_defaults_stage.name));              \
    CHECK(same(mine.name, c_stage.name));                             \
    CHECK(same(back_stage.name, c_stage.name));                       \
  }
#define SPINHASH_STAGE_ROUND_TRIP(id, Name, what)   \
  {                                                 \
    INFO("stage " #id);                             \
    const Name##Params& mine = edited.id;           \
    const Name##Params& back_stage = back.id;       \
    const auto& c_stage = c.id;                     \
    const auto& c_defaults_stage = c_defaults.id;   \
    SPINHASH_PARAMS_##id(SPINHASH_PARAM_ROUND_TRIP) \
  }
  SPINHASH_STAGES(SPINHASH_STAGE_ROUND_TRIP)
#undef SPINHASH_STAGE_ROUND_TRIP
#undef SPINHASH_PARAM_ROUND_TRIP
  CHECK(k > 100);
}

TEST_CASE("config fields: the C default config is the C++ default, field by field") {
  spinhash_config c;
  std::memset(&c, 0xA5, sizeof c);
  spinhash_default_config(&c);
  const RecognizerConfig defaults;
#define SPINHASH_DEFAULT(kind, name, lo, hi, flag, help) \
  {                                                      \
    INFO("field " #name);                                \
    CHECK(same(defaults.name, c.name));                  \
  }
  SPINHASH_CONFIG_FIELDS(SPINHASH_DEFAULT)
#undef SPINHASH_DEFAULT
#define SPINHASH_PARAM_DEFAULT(kind, name, def, lo, hi, flag, why) \
  {                                                                \
    INFO("field " #name);                                          \
    CHECK(same(mine.name, c_stage.name));                          \
  }
#define SPINHASH_STAGE_DEFAULT(id, Name, what)   \
  {                                              \
    const Name##Params& mine = defaults.id;      \
    const auto& c_stage = c.id;                  \
    SPINHASH_PARAMS_##id(SPINHASH_PARAM_DEFAULT) \
  }
  SPINHASH_STAGES(SPINHASH_STAGE_DEFAULT)
#undef SPINHASH_STAGE_DEFAULT
#undef SPINHASH_PARAM_DEFAULT
}

TEST_CASE("config fields: every statistic reaches the C struct") {
  RecognitionStats st;
  int k = 0;
  // Distinct non-zero values per field (bools true).
#define SPINHASH_SET_STAT(kind, name, member, json) \
  st.member = std::is_same<decltype(st.member), bool>::value ? 1 : static_cast<decltype(st.member)>(11 + k++);
  SPINHASH_STATS_FIELDS(SPINHASH_SET_STAT)
#undef SPINHASH_SET_STAT
  spinhash_stats c;
  std::memset(&c, 0, sizeof c);
  to_c_stats(st, &c);
#define SPINHASH_CHECK_STAT(kind, name, member, json)          \
  {                                                            \
    INFO("statistic " #name);                                  \
    CHECK(c.name != 0u);                                       \
    CHECK(c.name == static_cast<decltype(c.name)>(st.member)); \
  }
  SPINHASH_STATS_FIELDS(SPINHASH_CHECK_STAT)
#undef SPINHASH_CHECK_STAT
}

// --- The scene's lists (scene_fields.h) against SceneConfig, StreamConfig,
// SceneStats and StreamStats: same fields, same types.
namespace {

constexpr size_t width_SIZE = 1, width_F64 = 1, width_KINDS = kObjectKinds, width_SCENE = 1;
using CppType_SIZE = size_t;
using CppType_F64 = double;
using CppType_KINDS = uint32_t[kObjectKinds];
using CppType_SCENE = SceneStats;

constexpr size_t listed_scene_config() {
  size_t n = 0;
#define SPINHASH_COUNT(kind, name, lo, hi, flag, help) n += width_##kind;
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}
constexpr size_t listed_stream_config() {
  size_t n = 0;
#define SPINHASH_COUNT(kind, name, lo, hi, flag, help) n += width_##kind;
  SPINHASH_STREAM_CONFIG_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}
constexpr size_t listed_scene_stats() {
  size_t n = 0;
#define SPINHASH_COUNT(kind, name, key) n += width_##kind;
  SPINHASH_SCENE_STATS_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}
constexpr size_t listed_stream_stats() {
  size_t n = 0;
#define SPINHASH_COUNT(kind, name, key) n += width_##kind;
  SPINHASH_STREAM_STATS_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}

// The nested configs (SceneConfig::recognizer, StreamConfig::scene) are one
// initializer each and no entry.
static_assert(member_count<SceneConfig>() == listed_scene_config() + 1u,
              "SceneConfig and SPINHASH_SCENE_CONFIG_FIELDS (scene_fields.h) list different fields");
static_assert(member_count<StreamConfig>() == listed_stream_config() + 1u,
              "StreamConfig and SPINHASH_STREAM_CONFIG_FIELDS (scene_fields.h) list different fields");
static_assert(member_count<SceneStats>() == listed_scene_stats(),
              "SceneStats and SPINHASH_SCENE_STATS_FIELDS (scene_fields.h) list different fields");
static_assert(member_count<StreamStats>() == listed_stream_stats(),
              "StreamStats and SPINHASH_STREAM_STATS_FIELDS (scene_fields.h) list different fields");

#define SPINHASH_SAME_TYPE(kind, name, lo, hi, flag, help)                        \
  static_assert(std::is_same<decltype(SceneConfig::name), CppType_##kind>::value, \
                #name ": another type in SceneConfig than in scene_fields.h");
SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_SAME_TYPE)
#undef SPINHASH_SAME_TYPE
#define SPINHASH_SAME_TYPE(kind, name, lo, hi, flag, help)                         \
  static_assert(std::is_same<decltype(StreamConfig::name), CppType_##kind>::value, \
                #name ": another type in StreamConfig than in scene_fields.h");
SPINHASH_STREAM_CONFIG_FIELDS(SPINHASH_SAME_TYPE)
#undef SPINHASH_SAME_TYPE
#define SPINHASH_SAME_TYPE(kind, name, key)                                      \
  static_assert(std::is_same<decltype(SceneStats::name), CppType_##kind>::value, \
                #name ": another type in SceneStats than in scene_fields.h");
SPINHASH_SCENE_STATS_FIELDS(SPINHASH_SAME_TYPE)
#undef SPINHASH_SAME_TYPE
#define SPINHASH_SAME_TYPE(kind, name, key)                                       \
  static_assert(std::is_same<decltype(StreamStats::name), CppType_##kind>::value, \
                #name ": another type in StreamStats than in scene_fields.h");
SPINHASH_STREAM_STATS_FIELDS(SPINHASH_SAME_TYPE)
#undef SPINHASH_SAME_TYPE

// Just outside [lo, hi] (false when the range is the type's whole range).
bool below(uint32_t lo, uint32_t* v) {
  if (lo == 0u) return false;
  *v = lo - 1u;
  return true;
}
bool above(uint32_t hi, uint32_t* v) {
  if (hi == 0xFFFFFFFFu) return false;
  *v = hi + 1u;
  return true;
}
bool below(uint64_t lo, uint64_t* v) {
  if (lo == 0u) return false;
  *v = lo - 1u;
  return true;
}
bool above(uint64_t hi, uint64_t* v) {
  if (hi == ~0ull) return false;
  *v = hi + 1u;
  return true;
}
bool below(float lo, float* v) {
  *v = std::nextafter(lo, -std::numeric_limits<float>::infinity());
  return std::isfinite(lo);
}
bool above(float hi, float* v) {
  *v = std::nextafter(hi, std::numeric_limits<float>::infinity());
  return std::isfinite(hi);
}
bool below(int, bool*) { return false; }
bool above(int, bool*) { return false; }
bool below(int, double (*)[3]) { return false; }
bool above(int, double (*)[3]) { return false; }

}  // namespace

TEST_CASE("scene fields: the defaults are valid and a field just outside its range is refused") {
  REQUIRE(scene_config_valid(SceneConfig{}));
  REQUIRE(stream_config_valid(StreamConfig{}));
  int refused = 0;
#define SPINHASH_OUTSIDE(kind, name, lo, hi, flag, help)        \
  {                                                             \
    INFO("scene field " #name);                                 \
    SceneConfig c;                                              \
    if (below(lo, &c.name)) CHECK_FALSE(scene_config_valid(c)); \
    SceneConfig d;                                              \
    if (above(hi, &d.name)) CHECK_FALSE(scene_config_valid(d)); \
    ++refused;                                                  \
  }
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_OUTSIDE)
#undef SPINHASH_OUTSIDE
#define SPINHASH_OUTSIDE(kind, name, lo, hi, flag, help)         \
  {                                                              \
    INFO("stream field " #name);                                 \
    StreamConfig c;                                              \
    if (below(lo, &c.name)) CHECK_FALSE(stream_config_valid(c)); \
    StreamConfig d;                                              \
    if (above(hi, &d.name)) CHECK_FALSE(stream_config_valid(d)); \
    ++refused;                                                   \
  }
  SPINHASH_STREAM_CONFIG_FIELDS(SPINHASH_OUTSIDE)
#undef SPINHASH_OUTSIDE
  CHECK(refused > 30);
}

TEST_CASE("stage fields: the defaults are valid and a field just outside its range is refused") {
  REQUIRE(config_valid(RecognizerConfig{}));
  int checked = 0;
#define SPINHASH_PARAM_OUTSIDE(kind, name, def, lo, hi, flag, why)  \
  {                                                                 \
    INFO("field " << stage_name << "." #name);                      \
    RecognizerConfig c;                                             \
    if (below(lo, &(c.*member).name)) CHECK_FALSE(config_valid(c)); \
    RecognizerConfig d;                                             \
    if (above(hi, &(d.*member).name)) CHECK_FALSE(config_valid(d)); \
    ++checked;                                                      \
  }
#define SPINHASH_STAGE_OUTSIDE(id, Name, what)            \
  {                                                       \
    const char* stage_name = #id;                         \
    Name##Params StageParams::*member = &StageParams::id; \
    SPINHASH_PARAMS_##id(SPINHASH_PARAM_OUTSIDE)          \
  }
  SPINHASH_STAGES(SPINHASH_STAGE_OUTSIDE)
#undef SPINHASH_STAGE_OUTSIDE
#undef SPINHASH_PARAM_OUTSIDE
  CHECK(checked > 90);
}

TEST_CASE("the stage table runs the stages of stage_fields.h in their order, each switch its `enabled`") {
  const char* listed[] = {
#define SPINHASH_STAGE_NAME(id, Name, what) #id,
      SPINHASH_STAGES(SPINHASH_STAGE_NAME)
#undef SPINHASH_STAGE_NAME
  };
  REQUIRE(kStageCount == sizeof(listed) / sizeof(listed[0]));
  StageParams on;  // every switch on: carry's is off by default
  on.carry.enabled = true;
  StageParams off = on;
  off.ground.enabled = false;
  off.carry.enabled = false;
  off.transfer.enabled = false;
  off.focus.enabled = false;
  for (uint32_t i = 0; i < kStageCount; ++i) {
    INFO("stage ", listed[i]);
    const StageId id = kStageOrder[i];
    CHECK(std::string(stage_name(id)) == listed[i]);
    CHECK(static_cast<uint32_t>(id) == i);
    const std::string name = listed[i];
    CHECK(stage_enabled(id, on));
    CHECK(stage_enabled(id, StageParams{}) == (name != "carry"));
    CHECK(stage_enabled(id, off) ==
          !(name == "ground" || name == "carry" || name == "transfer" || name == "focus"));
  }
}
