#include "config/config_assign.hpp"

#include <cerrno>
#include <cstdlib>
#include <type_traits>

#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/presets.hpp"

namespace spinhash::host {
namespace {

// The whole text is one number; strtod/strtoull leave *end at what they did not read.
bool parse(const std::string& text, double* out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *out = std::strtod(text.c_str(), &end);
  return errno == 0 && *end == '\0';
}
bool parse(const std::string& text, unsigned long long* out) {
  if (text.empty() || text[0] == '-') return false;
  char* end = nullptr;
  errno = 0;
  *out = std::strtoull(text.c_str(), &end, 0);
  return errno == 0 && *end == '\0';
}

template <typename T, typename L, typename H>
bool set_number(const std::string& text, T* v, L lo, H hi) {
  using P = typename std::conditional<std::is_floating_point<T>::value, double, unsigned long long>::type;
  P p = 0;
  if (!parse(text, &p) || !(p >= static_cast<P>(lo) && p <= static_cast<P>(hi))) return false;  // NaN too
  *v = static_cast<T>(p);
  return true;
}
template <typename L, typename H>
bool set_U32(const std::string& t, uint32_t* v, L lo, H hi) {
  return set_number(t, v, lo, hi);
}
template <typename L, typename H>
bool set_U64(const std::string& t, uint64_t* v, L lo, H hi) {
  return set_number(t, v, lo, hi);
}
template <typename L, typename H>
bool set_F32(const std::string& t, float* v, L lo, H hi) {
  return set_number(t, v, lo, hi);
}
bool set_BOOL(const std::string& t, bool* v, int, int) {
  if (t != "0" && t != "1") return false;
  *v = t == "1";
  return true;
}
bool set_MODE(const std::string&, Mode*, int, int) { return false; }
bool set_VEC3D(const std::string&, double (*)[3], int, int) { return false; }

}  // namespace

bool assign_config_field(const std::string& assignment, RecognizerConfig* cfg, std::string* error) {
  const size_t eq = assignment.find('=');
  const std::string name = assignment.substr(0, eq),
                    value = eq == std::string::npos ? "" : assignment.substr(eq + 1);
  if (name == "preset") {  // a named configuration's fields (spinhash/presets.hpp)
    Preset preset;
    if (preset_from_name(value.c_str(), &preset)) {
      apply_preset(preset, cfg);
      return true;
    }
    *error = "no preset " + value + " (default, flight)";
    return false;
  }
#define SPINHASH_ASSIGN_FIELD(kind, field, lo, hi, flag, help)                            \
  if (name == #field) {                                                                   \
    if (set_##kind(value, &cfg->field, lo, hi)) return true;                              \
    *error = "bad value for " + name + " (" #kind ", range " #lo " - " #hi "): " + value; \
    return false;                                                                         \
  }
  SPINHASH_CONFIG_FIELDS(SPINHASH_ASSIGN_FIELD)
#undef SPINHASH_ASSIGN_FIELD
  *error = "no configuration field " + name;
  return false;
}

}  // namespace spinhash::host
