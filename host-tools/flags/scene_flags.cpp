#include "flags/scene_flags.hpp"

#include <algorithm>

#include "spinhash/limits.hpp"
#include "spinhash/scene_fields.h"

namespace spinhash::flags {
namespace {

// One registration per kind of SPINHASH_SCENE_CONFIG_FIELDS. A default of 0
// (max_tile_points: sized from the tile) is not shown; the help says.
template <typename T, typename L, typename H>
void add_number(CLI::App* cmd, T* v, L lo, H hi, const char* flag, const char* help) {
  CLI::Option* o = cmd->add_option(flag, *v, help)->check(CLI::Range(static_cast<T>(lo), static_cast<T>(hi)));
  if (*v != T{0}) o->capture_default_str();
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

}  // namespace

void add_scene_flags(CLI::App* cmd, SceneConfig* c, const std::vector<std::string>& only) {
  auto wanted = [&only](const char* flag) {
    return *flag != '\0' && (only.empty() || std::find(only.begin(), only.end(), flag) != only.end());
  };
#define SPINHASH_ADD_SCENE_FLAG(kind, name, lo, hi, flag, help) \
  if (wanted(flag)) add_##kind(cmd, &c->name, lo, hi, flag, help);
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_ADD_SCENE_FLAG)
#undef SPINHASH_ADD_SCENE_FLAG
}

}  // namespace spinhash::flags
