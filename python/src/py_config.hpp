// spinhash.Config: RecognizerConfig with one attribute and keyword argument
// per field of the field lists (config_fields.h, stage_fields.h, through
// host-tools/config/field_table.hpp), range-checked as the core checks them.
// A stage's field goes by its own name (unique across the stages), a
// stage's switch by <stage>_enabled; set_config_field also takes the
// stage.field key.
#pragma once
#include <pybind11/pybind11.h>

#include <string>

#include "spinhash/config.hpp"

namespace spinhash::python {

// Sets the field `key`, a Python name or a stage.field key (TypeError for an
// unknown field or a value of the wrong type, ValueError naming the field
// for a value outside its range).
void set_config_field(RecognizerConfig* cfg, const std::string& key, pybind11::handle value);

// Every setting of a dict (keyword arguments), in its order; an explicit
// has_viewpoint is applied last (setting the viewpoint turns it on).
void set_config_fields(RecognizerConfig* cfg, const pybind11::dict& settings);

// `config` (a spinhash.Config, or None for `base`) with `kwargs` applied, and
// checked whole (ValueError for a rule that joins fields, e.g. delta_max >= delta).
RecognizerConfig recognizer_config(const RecognizerConfig& base, pybind11::handle config,
                                   const pybind11::kwargs& kwargs);

}  // namespace spinhash::python
