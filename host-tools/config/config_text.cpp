#include "config/config_text.hpp"

#include <sstream>

#include "config/field_table.hpp"
#include "config/mode_name.hpp"
#include "spinhash/scene_fields.h"

namespace spinhash::host {

std::string config_text(const RecognizerConfig& c, bool with_mode) {
  std::ostringstream s;
  const char* sep = "";
  for (const ConfigField& f : config_fields()) {
    if (f.kind == FieldKind::MODE && !with_mode) continue;
    s << sep << f.key() << " ";
    switch (f.kind) {
      case FieldKind::MODE: {
        const Mode m = f.in<Mode>(c);
        s << mode_name(m);
        break;
      }
      case FieldKind::BOOL: s << (f.in<bool>(c) ? "on" : "off"); break;
      case FieldKind::U32: s << f.in<uint32_t>(c); break;
      case FieldKind::U64: s << f.in<uint64_t>(c); break;
      case FieldKind::F32: s << f.in<float>(c); break;
      case FieldKind::VEC3D: {
        const double(&v)[3] = f.in<double[3]>(c);
        s << v[0] << " " << v[1] << " " << v[2];
        break;
      }
    }
    sep = "; ";
  }
  return s.str();
}

std::string config_text(const SceneConfig& c) {
  std::ostringstream s;
  const char* sep = "";
#define SPINHASH_SCENE_FIELD_TEXT(kind, name, lo, hi, flag, help) \
  s << sep << #name << " " << c.name;                             \
  sep = "; ";
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_SCENE_FIELD_TEXT)
#undef SPINHASH_SCENE_FIELD_TEXT
  return s.str();
}

}  // namespace spinhash::host
