// Every recognizer setting as a row of one table, produced from the field
// lists (spinhash/config_fields.h: the top-level fields; stage_fields.h: each
// stage's), for the host's mirrors that walk them at run time: the command
// line's flags and `--set`, the experiments' configuration text, Python's
// keywords and attributes, and the documentation's checks.
#pragma once
#include <string>
#include <vector>

#include "spinhash/config.hpp"

namespace spinhash::host {

// The lists' kinds.
enum class FieldKind { MODE, BOOL, U32, U64, F32, VEC3D };

struct ConfigField {
  const char* stage;  // the stage's id (stage_fields.h), "" for a top-level field
  const char* name;   // the field's name in its struct
  FieldKind kind;
  long double lo, hi;                // the valid range (inclusive; BOOL, MODE and VEC3D: none to check here)
  const char* flag;                  // CLI11 option name(s), "" for none
  const char* help;                  // the list's one line
  void* (*at)(RecognizerConfig& c);  // the field in c

  // "stage.name", or "name" for a top-level field: what `--set` takes.
  std::string key() const;
  // Python's keyword and attribute: the name, or <stage>_enabled for a
  // stage's switch (the names are unique across the stages but for it).
  std::string flat() const;
  template <typename T>
  T& in(RecognizerConfig& c) const {
    return *static_cast<T*>(at(c));
  }
  template <typename T>
  const T& in(const RecognizerConfig& c) const {
    return *static_cast<const T*>(at(const_cast<RecognizerConfig&>(c)));
  }
};

// The top-level fields in list order, then each stage's in stage order.
const std::vector<ConfigField>& config_fields();

// The field whose key() or flat() is `name`; null when none.
const ConfigField* find_config_field(const std::string& name);

// The stages' ids in run order.
const std::vector<std::string>& stage_ids();

}  // namespace spinhash::host
