#include "config/config_assign.hpp"

#include <cerrno>
#include <cstdlib>
#include <sstream>

#include "config/field_table.hpp"
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

template <typename T, typename P>
bool set_number(const std::string& text, const ConfigField& f, RecognizerConfig* cfg) {
  P p = 0;
  if (!parse(text, &p) || !(p >= static_cast<P>(f.lo) && p <= static_cast<P>(f.hi))) return false;  // NaN too
  f.in<T>(*cfg) = static_cast<T>(p);
  return true;
}

bool set_field(const ConfigField& f, const std::string& value, RecognizerConfig* cfg) {
  switch (f.kind) {
    case FieldKind::BOOL:
      if (value != "0" && value != "1" && value != "false" && value != "true") return false;
      f.in<bool>(*cfg) = value == "1" || value == "true";
      return true;
    case FieldKind::U32: return set_number<uint32_t, unsigned long long>(value, f, cfg);
    case FieldKind::U64: return set_number<uint64_t, unsigned long long>(value, f, cfg);
    case FieldKind::F32: return set_number<float, double>(value, f, cfg);
    case FieldKind::MODE:
    case FieldKind::VEC3D: return false;
  }
  return false;
}

const char* kind_name(FieldKind k) {
  switch (k) {
    case FieldKind::MODE: return "MODE";
    case FieldKind::BOOL: return "BOOL";
    case FieldKind::U32: return "U32";
    case FieldKind::U64: return "U64";
    case FieldKind::F32: return "F32";
    case FieldKind::VEC3D: return "VEC3D";
  }
  return "?";
}

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
    *error = "no preset " + value + " (default, flight, full)";
    return false;
  }
  const ConfigField* f = find_config_field(name);
  if (f == nullptr) {
    *error = "no configuration field " + name + " (docs/api.md lists them: stage.field or a top-level field)";
    return false;
  }
  if (set_field(*f, value, cfg)) return true;
  std::ostringstream range;
  range << static_cast<double>(f->lo) << " - " << static_cast<double>(f->hi);
  *error = "bad value for " + f->key() + " (" + kind_name(f->kind) +
           (f->kind == FieldKind::U32 || f->kind == FieldKind::U64 || f->kind == FieldKind::F32
                ? ", range " + range.str()
                : std::string(f->kind == FieldKind::BOOL ? ", 0 or 1" : ", set by its own flag")) +
           "): " + value;
  return false;
}

}  // namespace spinhash::host
