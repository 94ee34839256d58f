#include "py_config.hpp"

#include <string>

#include "bindings.hpp"
#include "config_kinds.hpp"
#include "pipeline/mode_name.hpp"
#include "spinhash/config_fields.h"
#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"

namespace py = pybind11;

namespace spinhash::python {
namespace {

// Field names in SPINHASH_CONFIG_FIELDS order.
py::tuple field_names() {
  py::list names;
#define SPINHASH_PY_NAME(kind, name, lo, hi, flag, help) names.append(#name);
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_NAME)
#undef SPINHASH_PY_NAME
  return py::tuple(names);
}

// The valid range of each numeric setting, (lo, hi) inclusive, as the core checks it.
py::object range_of(float lo, float hi) { return py::make_tuple(shortest(lo), shortest(hi)); }
template <typename L, typename H>
py::object range_of(L lo, H hi) {
  return py::make_tuple(static_cast<unsigned long long>(lo), static_cast<unsigned long long>(hi));
}
py::dict field_ranges() {
  py::dict ranges;
#define SPINHASH_PY_RANGE_MODE(name, lo, hi)
#define SPINHASH_PY_RANGE_BOOL(name, lo, hi)
#define SPINHASH_PY_RANGE_VEC3D(name, lo, hi)
#define SPINHASH_PY_RANGE_U32(name, lo, hi) ranges[#name] = range_of(lo, hi);
#define SPINHASH_PY_RANGE_U64(name, lo, hi) ranges[#name] = range_of(lo, hi);
#define SPINHASH_PY_RANGE_F32(name, lo, hi) ranges[#name] = range_of(lo, hi);
#define SPINHASH_PY_RANGE(kind, name, lo, hi, flag, help) SPINHASH_PY_RANGE_##kind(name, lo, hi)
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_RANGE)
#undef SPINHASH_PY_RANGE
  return ranges;
}

// The mode words, in the MODE field's range ("bran", "sran", "sind").
py::tuple mode_names() {
  py::list names;
#define SPINHASH_PY_MODES_MODE(lo, hi) \
  for (int m = lo; m <= hi; ++m) names.append(pipeline::mode_name(Mode(m)));
#define SPINHASH_PY_MODES_BOOL(lo, hi)
#define SPINHASH_PY_MODES_U32(lo, hi)
#define SPINHASH_PY_MODES_U64(lo, hi)
#define SPINHASH_PY_MODES_F32(lo, hi)
#define SPINHASH_PY_MODES_VEC3D(lo, hi)
#define SPINHASH_PY_MODES(kind, name, lo, hi, flag, help) SPINHASH_PY_MODES_##kind(lo, hi)
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_MODES)
#undef SPINHASH_PY_MODES
  return py::tuple(names);
}

py::dict as_dict(const RecognizerConfig& c) {
  py::dict d;
#define SPINHASH_PY_GET(kind, name, lo, hi, flag, help) d[#name] = get_##kind(c.name);
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_GET)
#undef SPINHASH_PY_GET
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
#define SPINHASH_PY_SET(kind, name, lo, hi, flag, help) \
  if (key == #name) return set_##kind(c, &c->name, lo, hi, #name, value);
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_SET)
#undef SPINHASH_PY_SET
  throw py::type_error("unknown recognizer setting '" + key + "' (spinhash.Config.fields lists them)");
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
  if (c.delta_max < c.delta)
    throw py::value_error("delta_max (" + bound_text(double{c.delta_max}) + ") must be at least delta (" +
                          bound_text(double{c.delta}) + ")");
  if (required_workspace_bytes(c) == 0) throw py::value_error("invalid recognizer configuration");
  return c;
}

void bind_config(py::module_& m) {
  py::class_<RecognizerConfig> cls(m, "Config",
                                   "Recognition settings: one attribute and keyword argument per setting of "
                                   "the core's RecognizerConfig (Config.fields; docs/api.md).");
  cls.def(py::init(&from_kwargs), "Config(**settings): defaults, with the settings given");
  cls.attr("fields") = field_names();
  cls.attr("ranges") = field_ranges();
  cls.attr("modes") = mode_names();
// A BOOL field's help describes its CLI flag, which sets it to false.
#define SPINHASH_PY_DOC_MODE(help) help
#define SPINHASH_PY_DOC_BOOL(help) "False: " help
#define SPINHASH_PY_DOC_U32(help) help
#define SPINHASH_PY_DOC_U64(help) help
#define SPINHASH_PY_DOC_F32(help) help
#define SPINHASH_PY_DOC_VEC3D(help) help
#define SPINHASH_PY_PROPERTY(kind, name, lo, hi, flag, help)                                \
  cls.def_property(                                                                         \
      #name, [](const RecognizerConfig& c) { return get_##kind(c.name); },                  \
      [](RecognizerConfig& c, py::handle v) { set_##kind(&c, &c.name, lo, hi, #name, v); }, \
      SPINHASH_PY_DOC_##kind(help));
  SPINHASH_CONFIG_FIELDS(SPINHASH_PY_PROPERTY)
#undef SPINHASH_PY_PROPERTY
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
