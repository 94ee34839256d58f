#include "py_config.hpp"

#include <string>

#include "bindings.hpp"
#include "config/field_table.hpp"
#include "config/mode_name.hpp"
#include "config_kinds.hpp"
#include "spinhash/recognizer.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

using host::ConfigField;
using host::FieldKind;

py::object get_field(const ConfigField& f, const RecognizerConfig& c) {
  switch (f.kind) {
    case FieldKind::MODE: return get_MODE(f.in<Mode>(c));
    case FieldKind::BOOL: return get_BOOL(f.in<bool>(c));
    case FieldKind::U32: return get_U32(f.in<uint32_t>(c));
    case FieldKind::U64: return get_U64(f.in<uint64_t>(c));
    case FieldKind::F32: return get_F32(f.in<float>(c));
    case FieldKind::VEC3D: return get_VEC3D(f.in<double[3]>(c));
  }
  return py::none();
}

void set_field(const ConfigField& f, RecognizerConfig* c, py::handle v) {
  const std::string name = f.flat();
  const auto lo = static_cast<unsigned long long>(f.lo), hi = static_cast<unsigned long long>(f.hi);
  switch (f.kind) {
    case FieldKind::MODE:
      set_MODE(c, &f.in<Mode>(*c), static_cast<int>(f.lo), static_cast<int>(f.hi), name.c_str(), v);
      break;
    case FieldKind::BOOL: set_BOOL(c, &f.in<bool>(*c), 0, 1, name.c_str(), v); break;
    case FieldKind::U32: set_unsigned(&f.in<uint32_t>(*c), lo, hi, name.c_str(), v); break;
    case FieldKind::U64: set_unsigned(&f.in<uint64_t>(*c), lo, hi, name.c_str(), v); break;
    case FieldKind::F32:
      set_F32(c, &f.in<float>(*c), static_cast<float>(f.lo), static_cast<float>(f.hi), name.c_str(), v);
      break;
    case FieldKind::VEC3D: set_VEC3D(c, &f.in<double[3]>(*c), 0, 0, name.c_str(), v); break;
  }
}

// Python's names of the fields, in the lists' order.
py::tuple field_names() {
  py::list names;
  for (const ConfigField& f : host::config_fields()) names.append(f.flat());
  return py::tuple(names);
}

// Each Python name's key: stage.field for a stage's, the name at top level.
py::dict field_keys() {
  py::dict keys;
  for (const ConfigField& f : host::config_fields()) keys[py::str(f.flat())] = f.key();
  return keys;
}

// The valid range of each numeric setting, (lo, hi) inclusive, as the core checks it.
py::dict field_ranges() {
  py::dict ranges;
  for (const ConfigField& f : host::config_fields()) {
    if (f.kind == FieldKind::F32)
      ranges[py::str(f.flat())] =
          py::make_tuple(shortest(static_cast<float>(f.lo)), shortest(static_cast<float>(f.hi)));
    else if (f.kind == FieldKind::U32 || f.kind == FieldKind::U64)
      ranges[py::str(f.flat())] =
          py::make_tuple(static_cast<unsigned long long>(f.lo), static_cast<unsigned long long>(f.hi));
  }
  return ranges;
}

// The mode words, in the MODE field's range ("bran", "sran", "sind").
py::tuple mode_names() {
  py::list names;
  for (const ConfigField& f : host::config_fields())
    if (f.kind == FieldKind::MODE)
      for (int m = static_cast<int>(f.lo); m <= static_cast<int>(f.hi); ++m)
        names.append(host::mode_name(Mode(m)));
  return py::tuple(names);
}

py::dict as_dict(const RecognizerConfig& c) {
  py::dict d;
  for (const ConfigField& f : host::config_fields()) d[py::str(f.flat())] = get_field(f, c);
  return d;
}

std::string config_repr(const RecognizerConfig& c) {
  std::string s = "spinhash.Config(";
  bool first = true;
  for (auto item : as_dict(c)) {
    s += std::string(first ? "" : ", ") + std::string(py::str(item.first)) + "=" +
         std::string(py::repr(item.second));
    first = false;
  }
  return s + ")";
}

RecognizerConfig from_kwargs(const py::kwargs& kwargs) {
  RecognizerConfig c;
  set_config_fields(&c, kwargs);
  return c;
}

}  // namespace

void set_config_field(RecognizerConfig* c, const std::string& key, py::handle value) {
  const ConfigField* f = host::find_config_field(key);
  if (f == nullptr)
    throw py::type_error("unknown recognizer setting '" + key + "' (spinhash.Config.fields lists them)");
  set_field(*f, c, value);
}

void set_config_fields(RecognizerConfig* c, const py::dict& settings) {
  for (auto item : settings) set_config_field(c, py::cast<std::string>(item.first), item.second);
  // Setting the viewpoint turns it on; an explicit has_viewpoint (as in to_dict()) has the last word.
  if (settings.contains("has_viewpoint")) set_config_field(c, "has_viewpoint", settings["has_viewpoint"]);
}

RecognizerConfig recognizer_config(const RecognizerConfig& base, py::handle config,
                                   const py::kwargs& kwargs) {
  RecognizerConfig c = base;
  if (!config.is_none()) {
    if (!py::isinstance<RecognizerConfig>(config))
      throw py::type_error("config must be a spinhash.Config or None, got " + type_name(config));
    c = config.cast<RecognizerConfig>();
  }
  set_config_fields(&c, kwargs);
  if (c.draws.delta_max < c.draws.delta)
    throw py::value_error("delta_max (" + bound_text(double{c.draws.delta_max}) +
                          ") must be at least delta (" + bound_text(double{c.draws.delta}) + ")");
  if (required_workspace_bytes(c) == 0) throw py::value_error("invalid recognizer configuration");
  return c;
}

void bind_config(py::module_& m) {
  py::class_<RecognizerConfig> cls(m, "Config",
                                   "Recognition settings: one attribute and keyword argument per setting of "
                                   "the core's RecognizerConfig and its stages (Config.fields; Config.keys "
                                   "maps each to its stage.field; docs/api.md).");
  cls.def(py::init(&from_kwargs), "Config(**settings): defaults, with the settings given");
  cls.attr("fields") = field_names();
  cls.attr("keys") = field_keys();
  cls.attr("ranges") = field_ranges();
  cls.attr("modes") = mode_names();
  // A BOOL field whose CLI flag sets it to false says so first.
  for (const ConfigField& f : host::config_fields()) {
    const std::string doc =
        (f.kind == FieldKind::BOOL && *f.flag == '!' ? "False: " : "") + std::string(f.help);
    cls.def_property(
        f.flat().c_str(), [&f](const RecognizerConfig& c) { return get_field(f, c); },
        [&f](RecognizerConfig& c, py::handle v) { set_field(f, &c, v); }, doc.c_str());
  }
  cls.def("to_dict", &as_dict, "every setting by name");
  cls.def("copy", [](const RecognizerConfig& c) { return c; });
  cls.def("__copy__", [](const RecognizerConfig& c) { return c; });
  cls.def("__deepcopy__", [](const RecognizerConfig& c, const py::dict&) { return c; });
  // By settings, so that a Config reaches multiprocessing workers.
  cls.def(py::pickle([](const RecognizerConfig& c) { return as_dict(c); },
                     [](const py::dict& settings) {
                       RecognizerConfig c;
                       set_config_fields(&c, settings);
                       return c;
                     }));
  cls.def("__eq__",
          [](const RecognizerConfig& a, const RecognizerConfig& b) { return as_dict(a).equal(as_dict(b)); });
  cls.def("__repr__", &config_repr);
}

}  // namespace spinhash::python
