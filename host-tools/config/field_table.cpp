#include "config/field_table.hpp"

#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/stage_fields.h"

namespace spinhash::host {
namespace {

std::vector<ConfigField> build() {
  std::vector<ConfigField> rows;
#define SPINHASH_TOP_ROW(kind, name, lo, hi, flag, help)                               \
  rows.push_back(ConfigField{"", #name, FieldKind::kind, static_cast<long double>(lo), \
                             static_cast<long double>(hi), flag, help,                 \
                             [](RecognizerConfig& c) -> void* { return static_cast<void*>(&c.name); }});
  SPINHASH_CONFIG_FIELDS(SPINHASH_TOP_ROW)
#undef SPINHASH_TOP_ROW
  // Each stage's fields reach the config through the stage's member (kStage).
#define SPINHASH_STAGE_ROW(kind, name, def, lo, hi, flag, why)                                            \
  rows.push_back(ConfigField{                                                                             \
      stage_id, #name, FieldKind::kind, static_cast<long double>(lo), static_cast<long double>(hi), flag, \
      why, [](RecognizerConfig& c) -> void* { return static_cast<void*>(&(c.*kStage).name); }});
#define SPINHASH_STAGE_ROWS(id, Name, what)                                \
  {                                                                        \
    static constexpr Name##Params StageParams::*kStage = &StageParams::id; \
    const char* stage_id = #id;                                            \
    SPINHASH_PARAMS_##id(SPINHASH_STAGE_ROW)                               \
  }
  SPINHASH_STAGES(SPINHASH_STAGE_ROWS)
#undef SPINHASH_STAGE_ROWS
#undef SPINHASH_STAGE_ROW
  return rows;
}

}  // namespace

std::string ConfigField::key() const {
  return *stage == '\0' ? std::string(name) : std::string(stage) + "." + name;
}

std::string ConfigField::flat() const {
  return *stage != '\0' && std::string(name) == "enabled" ? std::string(stage) + "_enabled"
                                                          : std::string(name);
}

const std::vector<ConfigField>& config_fields() {
  static const std::vector<ConfigField> rows = build();
  return rows;
}

const ConfigField* find_config_field(const std::string& name) {
  for (const ConfigField& f : config_fields())
    if (f.key() == name || f.flat() == name) return &f;
  return nullptr;
}

const std::vector<std::string>& stage_ids() {
  static const std::vector<std::string> ids{
#define SPINHASH_STAGE_ID(id, Name, what) #id,
      SPINHASH_STAGES(SPINHASH_STAGE_ID)
#undef SPINHASH_STAGE_ID
  };
  return ids;
}

}  // namespace spinhash::host
