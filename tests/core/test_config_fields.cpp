// The field lists of spinhash/config_fields.h against the C++ structs they
// mirror: same fields, same types (at compile time), and every field through
// the C struct and back with a value that is not its default.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "c_api/config_bridge.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/recognizer.hpp"

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
  size_t n = 0;
#define SPINHASH_COUNT(kind, name, lo, hi, flag, help) n += width_##kind;
  SPINHASH_CONFIG_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}
constexpr size_t listed_stats(bool in_extract) {
  size_t n = 0;
#define SPINHASH_COUNT(kind, name, member, json) \
  n += starts_with(#member, "extract.") == in_extract ? 1u : 0u;
  SPINHASH_STATS_FIELDS(SPINHASH_COUNT)
#undef SPINHASH_COUNT
  return n;
}

static_assert(member_count<RecognizerConfig>() == listed_config_initializers(),
              "RecognizerConfig and SPINHASH_CONFIG_FIELDS (config_fields.h) list different fields");
static_assert(member_count<ExtractStats>() == listed_stats(true),
              "ExtractStats and the extract.* entries of SPINHASH_STATS_FIELDS differ");
static_assert(member_count<RecognitionStats>() == listed_stats(false) + 1u,
              "RecognitionStats and SPINHASH_STATS_FIELDS (config_fields.h) list different fields");

// --- Types: each kind's C++ type.
using CppType_MODE = Mode;
using CppType_BOOL = bool;
using CppType_U32 = uint32_t;
using CppType_U64 = uint64_t;
using CppType_F32 = float;
using CppType_VEC3D = double[3];
#define SPINHASH_SAME_TYPE(kind, name, lo, hi, flag, help)                             \
  static_assert(std::is_same<decltype(RecognizerConfig::name), CppType_##kind>::value, \
                #name ": another type in RecognizerConfig than in config_fields.h");
SPINHASH_CONFIG_FIELDS(SPINHASH_SAME_TYPE)
#undef SPINHASH_SAME_TYPE

template <typename T>
constexpr bool stat_fits(const char* kind) {
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
