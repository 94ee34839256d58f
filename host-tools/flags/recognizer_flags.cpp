#include "flags/recognizer_flags.hpp"

#include <map>
#include <string>

#include "pipeline/mode_name.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/presets.hpp"

namespace spinhash::flags {

using pipeline::mode_name;
using pipeline::mode_names;
namespace {

// One registration per kind of SPINHASH_CONFIG_FIELDS.
// By name: a transformer over the enum would print its raw bytes in --help.
void add_MODE(CLI::App* cmd, Mode* v, int, int, const char* flag, const char* help) {
  std::vector<std::string> names;
  for (const auto& entry : mode_names()) names.push_back(entry.first);
  cmd->add_option_function<std::string>(
         flag, [v](const std::string& name) { *v = mode_names().at(name); }, help)
      ->check(CLI::IsMember(names, CLI::ignore_case))
      ->default_str(mode_name(*v));
}
void add_BOOL(CLI::App* cmd, bool* v, int, int, const char* flag, const char* help) {
  cmd->add_flag(flag, *v, help);
}
template <typename T, typename L, typename H>
void add_number(CLI::App* cmd, T* v, L lo, H hi, const char* flag, const char* help) {
  cmd->add_option(flag, *v, help)
      ->check(CLI::Range(static_cast<T>(lo), static_cast<T>(hi)))
      ->capture_default_str();
}
template <typename L, typename H>
void add_U32(CLI::App* cmd, uint32_t* v, L lo, H hi, const char* flag, const char* help) {
  add_number(cmd, v, lo, hi, flag, help);
}
template <typename L, typename H>
void add_U64(CLI::App* cmd, uint64_t* v, L lo, H hi, const char* flag, const char* help) {
  add_number(cmd, v, lo, hi, flag, help);
}
template <typename L, typename H>
void add_F32(CLI::App* cmd, float* v, L lo, H hi, const char* flag, const char* help) {
  add_number(cmd, v, lo, hi, flag, help);
}
void add_VEC3D(CLI::App*, double (*)[3], int, int, const char*, const char*) {}  // --viewpoint, below

}  // namespace

void add_recognizer_flags(CLI::App* cmd, RecognizerConfig* c) {
  // First, so that its callback runs before the fields' flags, which override it.
  cmd->add_option_function<std::string>(
         "--preset",
         [c](const std::string& name) {
           Preset preset = Preset::kDefault;
           preset_from_name(name.c_str(), &preset);
           apply_preset(preset, c);
         },
         "a named configuration (include/spinhash/presets.hpp): default, or flight (about a third of "
         "the default's instructions per query, at a measured loss of accuracy: docs/results.md); the "
         "flags below override its fields")
      ->check(CLI::IsMember({"default", "flight"}));
#define SPINHASH_ADD_FLAG(kind, name, lo, hi, flag, help) \
  if (*(flag) != '\0') add_##kind(cmd, &c->name, lo, hi, flag, help);
  SPINHASH_CONFIG_FIELDS(SPINHASH_ADD_FLAG)
#undef SPINHASH_ADD_FLAG
  cmd->add_option_function<std::vector<double>>(
         "--viewpoint",
         [c](const std::vector<double>& v) {
           for (int a = 0; a < 3; ++a) c->viewpoint[a] = v[static_cast<size_t>(a)];
           c->has_viewpoint = true;
         },
         "sensor position X Y Z in the cloud's coordinates: normals turn towards it")
      ->expected(3);
}

}  // namespace spinhash::flags
