#include "flags/recognizer_flags.hpp"

#include <map>
#include <string>

#include "config/config_assign.hpp"
#include "config/field_table.hpp"
#include "config/mode_name.hpp"
#include "spinhash/presets.hpp"

namespace spinhash::flags {

using host::ConfigField;
using host::FieldKind;
using host::mode_name;
using host::mode_names;

namespace {

// By name: a transformer over the enum would print its raw bytes in --help.
void add_mode(CLI::App* cmd, Mode* v, const ConfigField& f) {
  std::vector<std::string> names;
  for (const auto& entry : mode_names()) names.push_back(entry.first);
  cmd->add_option_function<std::string>(
         f.flag, [v](const std::string& name) { *v = mode_names().at(name); }, f.help)
      ->check(CLI::IsMember(names, CLI::ignore_case))
      ->default_str(mode_name(*v));
}

template <typename T>
void add_number(CLI::App* cmd, T* v, const ConfigField& f) {
  cmd->add_option(f.flag, *v, f.help)
      ->check(CLI::Range(static_cast<T>(f.lo), static_cast<T>(f.hi)))
      ->capture_default_str();
}

// One registration per kind; the help names the field's key, which --set takes.
void add_flag(CLI::App* cmd, RecognizerConfig* c, const ConfigField& f) {
  switch (f.kind) {
    case FieldKind::MODE: add_mode(cmd, &f.in<Mode>(*c), f); break;
    case FieldKind::BOOL: cmd->add_flag(f.flag, f.in<bool>(*c), f.help); break;
    case FieldKind::U32: add_number(cmd, &f.in<uint32_t>(*c), f); break;
    case FieldKind::U64: add_number(cmd, &f.in<uint64_t>(*c), f); break;
    case FieldKind::F32: add_number(cmd, &f.in<float>(*c), f); break;
    case FieldKind::VEC3D: break;  // --viewpoint, below
  }
}

void add_preset(CLI::App* cmd, RecognizerConfig* c) {
  cmd->add_option_function<std::string>(
         "--preset",
         [c](const std::string& name) {
           Preset preset = Preset::kDefault;
           preset_from_name(name.c_str(), &preset);
           apply_preset(preset, c);
         },
         "a named configuration (include/spinhash/presets.hpp): default (the cascade: a flight pass, the "
         "full "
         "pass when it is not confident), full (the full pass alone) or flight (the flight pass alone); the "
         "other flags and --set override its fields")
      ->check(CLI::IsMember({"default", "flight", "full"}));
}

void add_set(CLI::App* cmd, RecognizerConfig* c) {
  cmd->add_option_function<std::vector<std::string>>(
         "--set", [c](const std::vector<std::string>& settings) { apply_settings(settings, c); },
         "STAGE.FIELD=VALUE: any stage parameter (docs/api.md lists them), or a top-level field by its "
         "name; applied after the other flags, in order (repeatable)")
      ->check(check_setting)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace

std::string check_setting(const std::string& setting) {
  RecognizerConfig probe;
  std::string error;
  return host::assign_config_field(setting, &probe, &error) ? std::string() : error;
}

void apply_settings(const std::vector<std::string>& settings, RecognizerConfig* cfg) {
  std::string error;
  for (const std::string& s : settings)
    if (!host::assign_config_field(s, cfg, &error)) throw CLI::ValidationError("--set", error);
}

void add_recognizer_flags(CLI::App* cmd, RecognizerConfig* c) {
  // First, so that its callback runs before the fields' flags, which override it.
  add_preset(cmd, c);
  for (const ConfigField& f : host::config_fields())
    if (*f.flag != '\0') add_flag(cmd, c, f);
  cmd->add_option_function<std::vector<double>>(
         "--viewpoint",
         [c](const std::vector<double>& v) {
           for (int a = 0; a < 3; ++a) c->viewpoint[a] = v[static_cast<size_t>(a)];
           c->has_viewpoint = true;
         },
         "sensor position X Y Z in the cloud's coordinates: normals turn towards it")
      ->expected(3);
  add_set(cmd, c);  // last: its callback runs after every flag's
}

void add_set_option(CLI::App* cmd, RecognizerConfig* c) {
  add_preset(cmd, c);
  add_set(cmd, c);
}

}  // namespace spinhash::flags
